// Areas 206..213 (set and actual values of the PLC logic module) and 216
// (one network's links, selected by word 0), manual 3.7, 3.8 and 3.11,
// through the device's PLC handlers (?GMXSPS, ?SPSSOLL, ?SPSIST).
#include "sim_table_areas.h"

#include "comm/camcon/table/table_map.h"
#include "comm/sim/camcon/sim_device.h"
#include "model/camcon/plc_network.h"

namespace cambench::comm::sim_table {

using table::Rk512Error;

namespace {

constexpr int kFirstPlcArea = 0x08;  // O in the ASCII protocol
constexpr int kHighNumberShift = 10;
// Area 216 words the model has no field for, kept per network.
constexpr int kWordsPerNetwork = 64;

Fields address(int area, int number) {
    return Fields().set("area", area).set("number", number);
}

// The ASCII area and number of area 216's selection word.
std::pair<int, int> selectedNetwork(const SimDevice& device) {
    const quint32 selection = quint32(device.tableState().plcLinkSelection);
    const int index = int((selection >> 8) & 0x3);
    const int number = int((selection & 0xFF) | (((selection >> kHighNumberShift) & 0x3) << 8));
    return {kFirstPlcArea + index, number};
}

qint64 ask(SimDevice& device, const char* query, const Fields& request, const char* field) {
    const std::optional<SimResult> result = device.call(kQuery, query, request);
    return result && result->kind == SimResult::Data ? result->fields.num(field) : 0;
}

SimAreaReply refusedBy(const std::optional<SimResult>& result, const QString& what) {
    if (result && result->kind != SimResult::Error) return {};
    return SimAreaReply::fail(Rk512Error::General, QStringLiteral("%1 refused").arg(what));
}

// The value area (206..213) as set (true) or actual value, and the ASCII area.
bool isSetValueArea(int area) {
    return area < table::kFirstPlcActualValueArea;
}
int asciiArea(int area) {
    return kFirstPlcArea + (area - (isSetValueArea(area) ? table::kFirstPlcSetValueArea
                                                         : table::kFirstPlcActualValueArea));
}

int linkKey(const SimDevice& device, int word) {
    return device.tableState().plcLinkSelection * kWordsPerNetwork + word;
}

}  // namespace

WordRead readPlcWord(SimDevice& device, int area, int word) {
    if (area != table::kPlcLinkArea) {
        const char* query = isSetValueArea(area) ? "SPSSOLL" : "SPSIST";
        return {qint32(ask(device, query, address(asciiArea(area), word), "value")),
                Rk512Error::None,
                {}};
    }
    const auto [plcArea, number] = selectedNetwork(device);
    const Fields network = address(plcArea, number);
    const int firstSymbol = table::tableWord(u"plc_link.symbol");
    if (word == table::tableWord(u"plc_link.network"))
        return {device.tableState().plcLinkSelection, Rk512Error::None, {}};
    if (word == table::tableWord(u"plc_link.value1"))
        return {qint32(ask(device, "SPSIST", network, "value")), Rk512Error::None, {}};
    if (word == table::tableWord(u"plc_link.value2"))
        return {qint32(ask(device, "GMXSPS", network, "reset")), Rk512Error::None, {}};
    if (word >= firstSymbol && word < firstSymbol + PlcNetwork::kSymbols) {
        const std::optional<SimResult> result = device.call(kQuery, "GMXSPS", network);
        const QList<qint64> symbols = result ? result->fields.words("symbols") : QList<qint64>();
        const int index = word - firstSymbol;
        return {index < symbols.size() ? qint32(symbols.at(index)) : 0, Rk512Error::None, {}};
    }
    return {device.tableState().words.value({area, linkKey(device, word)}), Rk512Error::None, {}};
}

SimAreaReply writePlcWord(SimDevice& device, int area, int word, qint32 value) {
    if (area != table::kPlcLinkArea) {
        const char* command = isSetValueArea(area) ? "SPSSOLL" : "SPSIST";
        return refusedBy(
            device.call(kCommand, command, address(asciiArea(area), word).set("value", value)),
            QStringLiteral("value of network %1 in area %2").arg(word).arg(area));
    }
    if (word == table::tableWord(u"plc_link.network")) {
        device.tableState().plcLinkSelection = value;
        return {};
    }
    const auto [plcArea, number] = selectedNetwork(device);
    const Fields network = address(plcArea, number);
    if (word == table::tableWord(u"plc_link.value1"))
        return refusedBy(device.call(kCommand, "SPSIST", Fields(network).set("value", value)),
                         QStringLiteral("actual value of the selected network"));
    const int firstSymbol = table::tableWord(u"plc_link.symbol");
    const bool isSymbol = word >= firstSymbol && word < firstSymbol + PlcNetwork::kSymbols;
    if (word == table::tableWord(u"plc_link.value2") || isSymbol) {
        const std::optional<SimResult> read = device.call(kQuery, "GMXSPS", network);
        if (!read || read->kind != SimResult::Data)
            return refusedBy(read, QStringLiteral("the selected network"));
        Fields fields = read->fields;
        if (isSymbol) {
            QList<qint64> symbols = fields.words("symbols");
            symbols.resize(PlcNetwork::kSymbols);
            symbols[word - firstSymbol] = quint16(value);
            fields.setWords("symbols", symbols);
        } else {
            fields.set("reset", quint16(value));
        }
        return refusedBy(device.call(kCommand, "GMXSPS", fields),
                         QStringLiteral("the selected network"));
    }
    device.tableState().words.insert({area, linkKey(device, word)}, value);
    return {};
}

}  // namespace cambench::comm::sim_table
