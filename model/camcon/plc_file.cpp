#include "plc_file.h"

#include "data_validation.h"
#include "model/atomic_file.h"
#include "model/camcon/camcon_family_id.h"
#include "model/file_read.h"
#include "model/json_file.h"

#include <QCoreApplication>
#include <QSet>

namespace cambench {

namespace {

const JsonFileType kPlcFile{"cambench-plc", kPlcFileFormatVersion, "PLC file",
                            camconFamilyId.latin1()};

constexpr char kLetters[] = "OPMX";

QString key(const char* text) {
    return QString::fromLatin1(text);
}

// The area of a network entry: a letter, or the number of older project files.
int readArea(JsonReader& reader, const QJsonObject& object, const QString& path) {
    const QString where = JsonReader::member(path, key("area"));
    const QJsonValue value = object.value(key("area"));
    if (value.isString()) {
        const QString letter = value.toString();
        for (int i = 0; i < 4; ++i) {
            if (letter == QLatin1Char(kLetters[i])) return PlcNetwork::O + i;
        }
        reader.fail(where, QCoreApplication::translate("cambench::model",
                                                       "the area \"%1\" is none of O, P, M, X")
                               .arg(letter));
        return PlcNetwork::O;
    }
    if (!object.contains(key("area"))) {
        reader.fail(path, QCoreApplication::translate("cambench::model", "\"area\" is missing"));
        return PlcNetwork::O;
    }
    return int(reader.integerValue(
        value, where, QCoreApplication::translate("cambench::model", "area (O, P, M or X)"),
        PlcNetwork::O, PlcNetwork::X));
}

PlcNetwork readNetwork(JsonReader& reader, const QJsonValue& value, const QString& path) {
    const QJsonObject object = reader.objectValue(value, path);
    PlcNetwork network;
    if (reader.failed()) return network;
    network.area = readArea(reader, object, path);
    network.number = int(reader.integer(
        object, path, key("number"),
        QCoreApplication::translate("cambench::model", "network number"), 0, kMaxPlcNumber));
    network.value = qint32(reader.integer(object, path, key("value"),
                                          QCoreApplication::translate("cambench::model", "value")));
    network.reset = quint16(
        reader.integer(object, path, key("reset"),
                       QCoreApplication::translate("cambench::model", "reset field"), 0, 0xFFFF));
    const QJsonArray symbols = reader.array(object, path, key("symbols"));
    const QString symbolsPath = JsonReader::member(path, key("symbols"));
    if (!reader.failed() && symbols.size() != PlcNetwork::kSymbols) {
        reader.fail(symbolsPath, QCoreApplication::translate(
                                     "cambench::model", "%1 symbols, expected %2 (%3 paths of %4)")
                                     .arg(symbols.size())
                                     .arg(PlcNetwork::kSymbols)
                                     .arg(PlcNetwork::kPaths)
                                     .arg(PlcNetwork::kSymbolsPerPath));
    }
    for (int k = 0; k < PlcNetwork::kSymbols && !reader.failed(); ++k) {
        network.symbols[std::size_t(k)] = quint16(reader.integerValue(
            symbols.at(k), JsonReader::element(symbolsPath, k),
            QCoreApplication::translate("cambench::model", "symbol"), 0, 0xFFFF));
    }
    return network;
}

}  // namespace

QString plcAreaLetter(int area) {
    const int index = area - PlcNetwork::O;
    return index >= 0 && index < 4 ? QString(QLatin1Char(kLetters[index])) : QStringLiteral("?");
}

QJsonObject plcNetworkToJson(const PlcNetwork& network) {
    QJsonArray symbols;
    for (quint16 symbol : network.symbols) symbols.append(int(symbol));
    return {{key("area"), plcAreaLetter(network.area)},
            {key("number"), network.number},
            {key("value"), network.value},
            {key("reset"), int(network.reset)},
            {key("symbols"), symbols}};
}

QJsonArray plcNetworksToJson(const QList<PlcNetwork>& networks) {
    QJsonArray array;
    for (const PlcNetwork& network : networks) array.append(plcNetworkToJson(network));
    return array;
}

QList<PlcNetwork> plcNetworksFromJson(JsonReader& reader, const QJsonArray& array,
                                      const QString& path) {
    QList<PlcNetwork> networks;
    QSet<QPair<int, int>> seen;
    for (int i = 0; i < array.size() && !reader.failed(); ++i) {
        const QString where = JsonReader::element(path, i);
        const PlcNetwork network = readNetwork(reader, array.at(i), where);
        const QPair<int, int> id(network.area, network.number);
        if (!reader.failed() && seen.contains(id)) {
            reader.fail(where,
                        QCoreApplication::translate("cambench::model", "network %1%2 appears twice")
                            .arg(plcAreaLetter(network.area))
                            .arg(network.number));
        }
        seen.insert(id);
        networks << network;
    }
    return networks;
}

QByteArray plcFileToJson(const QList<PlcNetwork>& networks) {
    QJsonObject root = jsonFileHeader(kPlcFile);
    root.insert(key("networks"), plcNetworksToJson(networks));
    return toIndentedJson(root);
}

Result<QList<PlcNetwork>> plcFileFromJson(const QByteArray& bytes) {
    const Result<QJsonObject> root = parseJsonFile(bytes, kPlcFile);
    if (!root) return root.error();
    JsonReader reader;
    QList<PlcNetwork> networks =
        plcNetworksFromJson(reader, reader.array(*root, {}, key("networks")), key("networks"));
    if (reader.failed()) return Error::invalidData(reader.problem() + QLatin1Char('.'));
    return networks;
}

Status savePlcFile(const QString& path, const QList<PlcNetwork>& networks) {
    return writeFileAtomically(path, plcFileToJson(networks));
}

Result<QList<PlcNetwork>> loadPlcFile(const QString& path) {
    return loadFileWith<QList<PlcNetwork>>(path, plcFileFromJson);
}

}  // namespace cambench
