#pragma once

// "Press 7", the machine of the machine tests: a CamCon "cams", an MC200
// (mc200v2) "plc" and a Compax3 "feed", each on its simulator's pty at
// 115200 baud. `plcVolatile` is the MC200's "volatile" list (issue 37),
// none when empty.

#include "e2e_support.h"

#include <QByteArray>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <QTest>

namespace cambench::e2e {

inline QJsonObject deviceAt(const QString& name, const QString& family, const QString& port) {
    return {{"name", name}, {"family", family}, {"port", port}, {"baud", 115200}};
}

inline QByteArray pressMachineFile(const QString& cams, const QString& plc, const QString& feed,
                                   const QJsonArray& plcVolatile = {}) {
    QJsonObject mc200 = deviceAt("plc", "mc1", plc);
    mc200.insert("protocol", "mc1");
    mc200.insert("variant", "mc200v2");
    if (!plcVolatile.isEmpty()) mc200.insert("volatile", plcVolatile);
    const QJsonArray devices{deviceAt("cams", "camcon", cams), mc200,
                             deviceAt("feed", "compax3", feed)};
    return QJsonDocument(QJsonObject{{"machine", "Press 7"}, {"devices", devices}}).toJson();
}

// Its three simulators started: the CamCon of EPROM 03.05.2001, the MC200
// V2, the Compax3 S150V4, each with the arguments given besides.
inline void startPress(SimSession& cams, SimSession& plc, SimSession& feed,
                       const QStringList& camsArgs = {}, const QStringList& feedArgs = {}) {
    START_SIM(cams, QStringList{"--eprom", "03.05.2001"} + camsArgs);
    START_SIM(plc, {"--variant", "mc200v2"});
    START_SIM(feed, QStringList{"--drive-type", "S150V4"} + feedArgs);
}

}  // namespace cambench::e2e
