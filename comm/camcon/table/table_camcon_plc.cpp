// The PLC logic module: links in area 216, set values 206..209, actual
// values 210..213. Networks are numbered from 0 as the model (and the ASCII
// protocol) numbers them; table word n-1 = network n counts from 1 (notes 5).
#include "table_camcon.h"
#include "table_map.h"

#include "comm/device/error_context.h"

#include <QCoreApplication>

namespace cambench::comm::table {

namespace {

// Area 216 word 0: O 0, P 256, M 512, X 768 + the 0-based number; numbers
// above 255 carry their high bits in bits 10-11 (firmware from 8/2008).
constexpr int kNetworksPerArea = 256;
constexpr int kHighNumberShift = 10;

Result<int> areaIndex(int area, int number) {
    const int index = area - PlcNetwork::O;
    if (index < 0 || index > 3 || number < 0) {
        return Error::usage(
            QCoreApplication::translate("cambench::comm",
                                        "%1 does not exist (areas O, P, M, X; numbers from 0)")
                .arg(PlcNetwork::describe(area, number)));
    }
    return index;
}

qint32 networkSelector(int index, int number) {
    return index * kNetworksPerArea + (number % kNetworksPerArea) +
           ((number / kNetworksPerArea) << kHighNumberShift);
}

}  // namespace

Result<PlcNetwork> TableCamCon::readPlcNetwork(int area, int number) {
    const QString what = QCoreApplication::translate("cambench::comm", "reading %1")
                             .arg(PlcNetwork::describe(area, number));
    const Result<int> index = areaIndex(area, number);
    if (!index) return index.error();
    const Status selected = m_link.writeWord(kPlcLinkArea, tableWord(u"plc_link.network"),
                                             networkSelector(*index, number));
    if (!selected) return inContext(what, selected.error());
    const int first = tableWord(u"plc_link.block_type");
    const int symbols = tableWord(u"plc_link.symbol");
    const Result<QList<qint32>> words = m_link.readWords(
        kPlcLinkArea, first, tableWord(u"plc_link.symbol", PlcNetwork::kSymbols - 1) - first + 1);
    if (!words) return inContext(what, words.error());
    const Result<qint32> setValue = m_link.readWord(kFirstPlcSetValueArea + *index, number);
    if (!setValue) return inContext(what, setValue.error());
    PlcNetwork network;
    network.area = area;
    network.number = number;
    network.value = *setValue;
    network.reset = quint16(words->at(tableWord(u"plc_link.value2") - first));
    for (int i = 0; i < PlcNetwork::kSymbols; ++i)
        network.symbols[size_t(i)] = quint16(words->at(symbols - first + i));
    return network;
}

Status TableCamCon::writePlcNetwork(const PlcNetwork& network) {
    const QString what = QCoreApplication::translate("cambench::comm", "writing %1")
                             .arg(PlcNetwork::describe(network.area, network.number));
    const Result<int> index = areaIndex(network.area, network.number);
    if (!index) return index.error();
    const Status selected = m_link.writeWord(kPlcLinkArea, tableWord(u"plc_link.network"),
                                             networkSelector(*index, network.number));
    if (!selected) return inContext(what, selected.error());
    // Block type, value 1 and 3 and the shift mode are not in the model:
    // they stay as the device has them.
    const Status reset =
        m_link.writeWord(kPlcLinkArea, tableWord(u"plc_link.value2"), network.reset);
    if (!reset) return inContext(what, reset.error());
    QList<qint32> symbols;
    for (quint16 symbol : network.symbols) symbols.append(symbol);
    const Status links = m_link.writeWords(kPlcLinkArea, tableWord(u"plc_link.symbol"), symbols);
    if (!links) return inContext(what, links.error());
    const Status value =
        m_link.writeWord(kFirstPlcSetValueArea + *index, network.number, network.value);
    if (!value) return inContext(what, value.error());
    return success();
}

Result<qint32> TableCamCon::readPlcActual(int area, int number) {
    const Result<int> index = areaIndex(area, number);
    if (!index) return index.error();
    const Result<qint32> value = m_link.readWord(kFirstPlcActualValueArea + *index, number);
    if (!value)
        return inContext(
            QCoreApplication::translate("cambench::comm", "reading the actual value of %1")
                .arg(PlcNetwork::describe(area, number)),
            value.error());
    return value;
}

Result<qint32> TableCamCon::readPlcSetpoint(int area, int number) {
    const Result<int> index = areaIndex(area, number);
    if (!index) return index.error();
    const Result<qint32> value = m_link.readWord(kFirstPlcSetValueArea + *index, number);
    if (!value)
        return inContext(
            QCoreApplication::translate("cambench::comm", "reading the set value of %1")
                .arg(PlcNetwork::describe(area, number)),
            value.error());
    return value;
}

}  // namespace cambench::comm::table
