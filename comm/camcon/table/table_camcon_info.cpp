// Identity, status, error reset and program change of the table interface.
#include "short_client.h"
#include "table_camcon.h"
#include "table_map.h"
#include "table_word_block.h"

#include "comm/device/error_context.h"

#include <QCoreApplication>

namespace cambench::comm::table {

namespace {

constexpr int kEpromDateWords = 3;
constexpr int kBitsPerWord = 32;

// Area 201 words 31..33: the EPROM date in ASCII, the first character in
// the high byte of each word (provisional, table_map.cpp).
QString epromDateText(const WordBlock& block) {
    QByteArray text;
    for (int i = 0; i < kEpromDateWords; ++i) {
        const quint32 word = quint32(block.at(u"status.eprom_date", i));
        for (int shift = 24; shift >= 0; shift -= 8) text.append(char((word >> shift) & 0xFF));
    }
    const qsizetype nul = text.indexOf('\0');
    if (nul >= 0) text.truncate(nul);
    return QString::fromLatin1(text.trimmed());
}

// One number of DeviceInfo and the table word it is (area, map key).
struct InfoWord {
    int area;
    const char16_t* key;
    int DeviceInfo::*member;
};
const InfoWord kInfoWords[] = {
    {kConfigArea, u"config.device_number", &DeviceInfo::deviceNumber},
    {kSystemArea, u"system.hardware_outputs", &DeviceInfo::outputs},
    {kSystemArea, u"system.hardware_inputs", &DeviceInfo::inputs},
    {kSystemArea, u"system.dead_time_outputs", &DeviceInfo::deadTimeOutputs},
    {kStatusArea, u"status.min_actual_value", &DeviceInfo::minPosition},
    {kStatusArea, u"status.max_actual_value", &DeviceInfo::maxPosition},
    {kStatusArea, u"status.max_dead_time", &DeviceInfo::maxDeadTime},
    {kStatusArea, u"status.cpu_frequency", &DeviceInfo::cpuClock},
    {kStatusArea, u"status.temperature", &DeviceInfo::temperature},
    {kStatusArea, u"status.free_cams", &DeviceInfo::freeCams},
    {kStatusArea, u"status.programmed_cams", &DeviceInfo::programmedCams},
    {kStatusArea, u"status.programmed_dead_times", &DeviceInfo::programmedDeadTimes},
    {kStatusArea, u"status.ram_size", &DeviceInfo::ramSize},
    {kStatusArea, u"status.free_ram", &DeviceInfo::ramFree},
    {kStatusArea, u"status.serial_eeprom_size", &DeviceInfo::serialEepromSize},
    {kStatusArea, u"status.parallel_eeprom_size", &DeviceInfo::parallelEepromSize},
};

// `count` bits from words of 32, bit 0 of the first word = number 1.
QList<bool> bitsOf(const QList<qint32>& words, int count) {
    QList<bool> bits(count, false);
    for (int i = 0; i < count && i / kBitsPerWord < words.size(); ++i)
        bits[i] = (quint32(words.at(i / kBitsPerWord)) >> (i % kBitsPerWord)) & 1;
    return bits;
}

}  // namespace

Result<DeviceInfo> TableCamCon::readInfo() {
    const QString what =
        QCoreApplication::translate("cambench::comm", "reading the device identity (data area %1)");
    const Result<WordBlock> status =
        WordBlock::read(m_link, kStatusArea, u"status.plc_boost", u"status.device_status");
    if (!status) return inContext(what.arg(kStatusArea), status.error());
    const Result<WordBlock> system = WordBlock::read(
        m_link, kSystemArea, u"system.dead_time_outputs", u"system.hardware_outputs");
    if (!system) return inContext(what.arg(kSystemArea), system.error());
    const Result<WordBlock> config =
        WordBlock::read(m_link, kConfigArea, u"config.device_number", u"config.serial_mode");
    if (!config) return inContext(what.arg(kConfigArea), config.error());

    DeviceInfo info;
    info.epromDate = epromDateText(*status);
    // ?GSIO has one "3964R" (4) for the table modes 4 (n96) and 5 (e38).
    info.protocol = qMin(config->at(u"config.serial_mode"), 4);
    info.programs = status->at(u"status.max_program") + 1;
    for (const InfoWord& word : kInfoWords) {
        const WordBlock& block = word.area == kStatusArea   ? *status
                                 : word.area == kSystemArea ? *system
                                                            : *config;
        info.*word.member = block.at(QStringView(word.key));
    }
    return info;
}

Result<DeviceStatus> TableCamCon::readStatus(int outputs, int inputs) {
    DeviceStatus status;
    // The axis moves between telegrams: the outputs are read right after
    // the position so that the two shown together belong together.
    const Result<WordBlock> axis =
        WordBlock::read(m_link, kStatusArea, u"status.actual_value", u"status.speed");
    if (!axis)
        return inContext(QCoreApplication::translate("cambench::comm", "reading the actual value"),
                         axis.error());
    status.position = axis->at(u"status.actual_value");
    status.speed = axis->at(u"status.speed");

    // No virtual inputs: without the PLC logic module the device ANDs them
    // with its outputs, so even zeros would switch outputs off.
    const Result<ShortStatus> decoded = m_short.status();
    if (!decoded) return decoded.error();
    status.activeProgram = decoded->program;
    status.errorState = decoded->deviceStatus;
    status.outputs = decoded->outputs.mid(0, outputs);
    while (status.outputs.size() < outputs) status.outputs.append(false);

    const TableEntry* inputWords = findTableEntry(u"io.inputs");
    const int words = qMin(inputWords->count, (inputs + kBitsPerWord - 1) / kBitsPerWord);
    if (words > 0) {
        const Result<QList<qint32>> bits = m_link.readWords(kIoArea, inputWords->firstWord, words);
        if (!bits)
            return inContext(QCoreApplication::translate("cambench::comm", "reading the inputs"),
                             bits.error());
        status.inputs = bitsOf(*bits, inputs);
    }
    return status;
}

Status TableCamCon::resetError() {
    return m_short.resetErrors();
}

Status TableCamCon::selectProgram(int program) {
    return m_short.changeProgram(program);
}

}  // namespace cambench::comm::table
