#pragma once

// "Press 7", the machine of the machine tests: a CamCon "cams", an MC200
// (mc200v2) "plc" and a Compax3 "feed", each on its simulator's pty at
// 115200 baud. `plcVolatile` is the MC200's "volatile" list (issue 37),
// none when empty.

#include <QByteArray>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>

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

}  // namespace cambench::e2e
