#pragma once

// The one reader and writer of PLC networks as JSON: inside project files
// ("plcNetworks") and as a PLC file of its own (cambench-cli plc
// read/write): {"format":"cambench-plc","version":1,"networks":[{"area":"M",
// "number":3,"value":2500,"reset":0,"symbols":[30 words]}, ...]}.
// Areas are written as letters O, P, M, X; the numbers 8..11 of older
// project files are read too.

#include "model/json_reader.h"
#include "model/result.h"
#include "plc_network.h"

#include <QByteArray>
#include <QJsonArray>
#include <QJsonObject>
#include <QList>

namespace cambench {

constexpr int kPlcFileFormatVersion = 1;

// "O", "P", "M", "X"; "?" for an unknown area.
QString plcAreaLetter(int area);

QJsonObject plcNetworkToJson(const PlcNetwork& network);
QJsonArray plcNetworksToJson(const QList<PlcNetwork>& networks);
// Reads the array at `path`; problems (with their JSON path) go to
// `reader`. Refuses a network listed twice.
QList<PlcNetwork> plcNetworksFromJson(JsonReader& reader, const QJsonArray& array,
                                      const QString& path);

QByteArray plcFileToJson(const QList<PlcNetwork>& networks);
Result<QList<PlcNetwork>> plcFileFromJson(const QByteArray& bytes);
Status savePlcFile(const QString& path, const QList<PlcNetwork>& networks);
// Errors start with the file's path.
Result<QList<PlcNetwork>> loadPlcFile(const QString& path);

}  // namespace cambench
