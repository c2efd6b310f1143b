// Areas 201 (status, actual value, program, programming program) and 202
// (inputs, outputs, flags), manual 3.2 and 3.3. Most values come from the
// same handlers that answer the ASCII queries.
#include "sim_table_areas.h"

#include "comm/camcon/table/table_map.h"
#include "comm/sim/camcon/sim_device.h"

#include <cmath>

namespace cambench::comm::sim_table {

using table::Rk512Error;

namespace {

constexpr int kBitsPerWord = 32;
constexpr int kEpromDateBytes = 12;            // 3 words; the date and its NUL fill 11
constexpr qint32 kMicrosecondsPerTenth = 100;  // ?GZYKLIST counts 0.1 ms, the table µs
constexpr qint32 kCpuColdfire = 1;
constexpr quint32 kDeleteProgramBit = 0x80000000u;

// A number from the ASCII handler of `query`; 0 when it has none.
qint64 ask(SimDevice& device, const char* query, const char* field = "value") {
    const std::optional<SimResult> result = device.call(kQuery, query);
    return result && result->kind == SimResult::Data ? result->fields.num(field) : 0;
}

SimAreaReply refusedBy(const std::optional<SimResult>& result, const QString& what) {
    if (result && result->kind != SimResult::Error) return {};
    return SimAreaReply::fail(Rk512Error::General, QStringLiteral("%1 refused").arg(what));
}

qint32 epromDateWord(const SimDevice& device, int index) {
    QByteArray date = device.profile().epromDate.left(kEpromDateBytes - 1);
    date.append(QByteArray(kEpromDateBytes - date.size(), '\0'));
    quint32 word = 0;
    for (int i = 0; i < 4; ++i) word = (word << 8) | quint8(date.at(index * 4 + i));
    return qint32(word);
}

qint32 bitWord(int index, int count, const std::function<bool(int)>& isSet) {
    quint32 word = 0;
    for (int bit = 0; bit < kBitsPerWord; ++bit) {
        const int number = index * kBitsPerWord + bit;
        if (number < count && isSet(number)) word |= 1u << bit;
    }
    return qint32(word);
}

bool outputOn(SimDevice& device, int output) {
    return device.axis().running() &&
           device.state().cams.isOn(device.state().activeProgram, output, device.axis().position());
}

// The word of `key`, when something other than a stored word answers it.
std::optional<qint32> statusWord(SimDevice& device, const QString& key, int index) {
    const SimProfile& profile = device.profile();
    // clang-format off
    const QList<std::pair<const char*, std::function<qint32()>>> sources{
        {"status.actual_value", [&] { return device.axis().position(); }},
        {"status.speed", [&] { return qint32(std::lround(device.axis().unitsPerSecond())); }},
        {"status.program", [&] { return device.state().activeProgram; }},
        {"status.plc_boost", [&] { return qint32(ask(device, "GBOOST")); }},
        {"status.cpu_frequency", [&] { return qint32(ask(device, "GCPUCLK")); }},
        {"status.temperature", [&] { return qint32(ask(device, "GTEMP")); }},
        {"status.free_cams", [&] { return qint32(ask(device, "MEEFREE")); }},
        {"status.programmed_cams", [&] { return qint32(ask(device, "MEENOCK")); }},
        {"status.max_dead_time", [&] { return qint32(ask(device, "GTZKMAX")); }},
        {"status.ram_size", [&] { return qint32(ask(device, "MRAMMAX")); }},
        {"status.free_ram", [&] { return qint32(ask(device, "MRAMFREE")); }},
        {"status.serial_eeprom_size", [&] { return qint32(ask(device, "MEES")); }},
        {"status.parallel_eeprom_size", [&] { return qint32(ask(device, "MPEE")); }},
        {"status.min_actual_value", [&] { return profile.minPosition; }},
        {"status.max_actual_value", [&] { return profile.maxPosition; }},
        {"status.max_program", [&] { return qint32(profile.programs - 1); }},
        {"status.programmed_dead_times", [&] { return qint32(ask(device, "MEETZK")); }},
        {"status.eprom_date", [&] { return epromDateWord(device, index); }},
        {"status.device_status", [&] { return device.runtime().errorState; }},
        {"status.cpu_type", [] { return kCpuColdfire; }},
        {"status.cycle_time", [&] { return qint32(ask(device, "GZYKLIST") * kMicrosecondsPerTenth); }},
        {"status.programming_program", [&] { return programmingProgram(device); }},
        {"status.copy_program", [&] { return programmingProgram(device); }},
        {"io.outputs", [&] { return bitWord(index, profile.outputs, [&](int o) { return outputOn(device, o); }); }},
        // Input 1 reports "running", the others are open (as ?ETAB).
        {"io.inputs", [&] { return bitWord(index, profile.inputs, [&](int i) { return i == 0 && device.axis().running(); }); }},
        {"io.virtual_inputs", [&] {
             const QByteArray bytes = device.runtime().vInputs;
             return bitWord(index, int(bytes.size()) * 8, [&](int v) { return (quint8(bytes.at(v / 8)) >> (v % 8)) & 1; });
         }},
    };
    // clang-format on
    for (const auto& [name, source] : sources) {
        if (key == QLatin1String(name)) return source();
    }
    return std::nullopt;
}

}  // namespace

WordRead readStatusWord(SimDevice& device, int area, int word) {
    const std::optional<table::TableLocation> location = table::locateTableWord(area, word);
    if (!location) return {0, Rk512Error::None, {}};
    const std::optional<qint32> value =
        statusWord(device, QLatin1String(location->entry->key), location->index);
    // Otherwise a stored word (select mode, switch value) or 0 (analogue
    // values and counters the simulator does not keep).
    return {value ? *value : device.tableState().words.value({area, word}), Rk512Error::None, {}};
}

SimAreaReply writeStatusWord(SimDevice& device, int area, int word, qint32 value) {
    const std::optional<table::TableLocation> location = table::locateTableWord(area, word);
    if (!location || !table::canWrite(location->entry->access)) {
        return SimAreaReply::fail(
            Rk512Error::General,
            QStringLiteral("word %1 of area %2 is read-only").arg(word).arg(area));
    }
    const QString key = QLatin1String(location->entry->key);
    SimTableState& table = device.tableState();
    if (key == QLatin1String("status.actual_value")) {
        device.axis().setPosition(value);
        return {};
    }
    if (key == QLatin1String("status.program"))
        return refusedBy(device.call(kCommand, "PAU", Fields().set("value", value)),
                         QStringLiteral("program %1").arg(value));
    if (key == QLatin1String("status.programming_program")) {
        if (value != -1 && (value < 0 || value >= device.profile().programs))
            return SimAreaReply::fail(Rk512Error::General,
                                      QStringLiteral("programming program %1").arg(value));
        table.programmingProgram = value;
        return {};
    }
    if (key == QLatin1String("status.copy_program")) {
        const quint32 bits = quint32(value);
        const qint64 program = bits & ~kDeleteProgramBit;
        if (bits & kDeleteProgramBit)
            return refusedBy(device.call(kCommand, "PDEL", Fields().set("program", program)),
                             QStringLiteral("deleting program %1").arg(program));
        return refusedBy(
            device.call(kCommand, "PCPY",
                        Fields().set("target", program).set("source", programmingProgram(device))),
            QStringLiteral("copying to program %1").arg(program));
    }
    if (key == QLatin1String("status.programming_select_mode") && (value < 0 || value > 2))
        return SimAreaReply::fail(Rk512Error::General, QStringLiteral("select mode %1").arg(value));
    if (key == QLatin1String("io.virtual_inputs")) {
        QByteArray& bytes = device.runtime().vInputs;
        bytes.resize(qMax<qsizetype>(bytes.size(), (location->index + 1) * 4), '\0');
        for (int i = 0; i < 4; ++i)
            bytes[location->index * 4 + i] = char((quint32(value) >> (8 * i)) & 0xFF);
        return {};
    }
    table.words.insert({area, word}, value);
    return {};
}

}  // namespace cambench::comm::sim_table
