#include "ascii_camcon.h"

#include <QCoreApplication>
#include "ascii_support.h"

namespace cambench::comm {

using namespace client;

Result<PlcNetwork> AsciiCamCon::readPlcNetwork(int area, int number) {
    const Result<Fields> reply =
        m_link.call('?', "GMXSPS", Fields{{"area", qint64(area)}, {"number", qint64(number)}});
    if (!reply) {
        return inContext(QCoreApplication::translate("cambench::comm", "reading %1 (?GMXSPS)")
                             .arg(PlcNetwork::describe(area, number)),
                         reply.error());
    }
    PlcNetwork network;
    network.area = area;
    network.number = number;
    network.value = qint32(reply->num("value"));
    network.reset = quint16(reply->num("reset"));
    const QList<qint64> words = reply->words("symbols");
    for (int i = 0; i < PlcNetwork::kSymbols && i < words.size(); ++i) {
        network.symbols[size_t(i)] = quint16(words.at(i));
    }
    return network;
}

Status AsciiCamCon::writePlcNetwork(const PlcNetwork& network) {
    Fields fields{{"area", qint64(network.area)},
                  {"number", qint64(network.number)},
                  {"value", qint64(network.value)},
                  {"reset", qint64(network.reset)}};
    QList<qint64> words;
    for (quint16 symbol : network.symbols) words.append(symbol);
    fields.setWords("symbols", words);
    const Result<Fields> reply = m_link.call('!', "GMXSPS", fields);
    if (!reply) {
        return inContext(QCoreApplication::translate("cambench::comm", "writing %1 (!GMXSPS)")
                             .arg(PlcNetwork::describe(network.area, network.number)),
                         reply.error());
    }
    return success();
}

Result<qint32> AsciiCamCon::readPlcActual(int area, int number) {
    const Result<Fields> reply =
        m_link.call('?', "SPSIST", Fields{{"area", qint64(area)}, {"number", qint64(number)}});
    if (!reply) {
        return inContext(QCoreApplication::translate("cambench::comm",
                                                     "reading the actual value of %1 (?SPSIST)")
                             .arg(PlcNetwork::describe(area, number)),
                         reply.error());
    }
    return qint32(reply->num("value"));
}

Result<qint32> AsciiCamCon::readPlcSetpoint(int area, int number) {
    const Result<Fields> reply =
        m_link.call('?', "SPSSOLL", Fields{{"area", qint64(area)}, {"number", qint64(number)}});
    if (!reply) {
        return inContext(
            QCoreApplication::translate("cambench::comm", "reading the set value of %1 (?SPSSOLL)")
                .arg(PlcNetwork::describe(area, number)),
            reply.error());
    }
    return qint32(reply->num("value"));
}

}  // namespace cambench::comm
