#include "device_identity.h"

#include <QCoreApplication>
#include <QJsonValue>
#include <QSet>

namespace cambench {

namespace {

QString valuesText(const QMap<QString, QString>& values) {
    QStringList parts;
    for (auto it = values.begin(); it != values.end(); ++it)
        parts << QStringLiteral("%1 %2").arg(it.key(), it.value());
    return parts.join(QLatin1String(", "));
}

}  // namespace

QString DeviceIdentity::text() const {
    return known() ? valuesText(m_values)
                   : QCoreApplication::translate("cambench::model", "not recorded");
}

QJsonObject DeviceIdentity::toJson() const {
    QJsonObject object;
    for (auto it = m_values.begin(); it != m_values.end(); ++it)
        object.insert(it.key(), it.value());
    return object;
}

Result<DeviceIdentity> DeviceIdentity::fromJson(const QJsonValue& value, const QString& where) {
    if (!value.isObject())
        return Error::invalidData(
            QCoreApplication::translate(
                "cambench::model",
                "%1 is not an object of names and texts ({\"serial\": \"...\"}).")
                .arg(where));
    DeviceIdentity identity;
    const QJsonObject object = value.toObject();
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (!it.value().isString() || it.key().isEmpty())
            return Error::invalidData(
                QCoreApplication::translate("cambench::model",
                                            "%1: \"%2\" must be a text, as CamBench wrote it.")
                    .arg(where, it.key()));
        identity.set(it.key(), it.value().toString());
    }
    return identity;
}

QString anotherDeviceText(const DeviceIdentity& expected, const DeviceIdentity& found) {
    if (!expected.known())
        return QCoreApplication::translate(
                   "cambench::model",
                   "which device this is cannot be told: no identity was recorded for it; found %1")
            .arg(found.text());
    QSet<QString> keys;
    for (const QString& key : expected.values().keys()) keys.insert(key);
    for (const QString& key : found.values().keys()) keys.insert(key);
    QMap<QString, QString> was;
    QMap<QString, QString> now;
    for (const QString& key : keys) {
        if (expected.value(key) == found.value(key)) continue;
        was.insert(key, expected.values().value(
                            key, QCoreApplication::translate("cambench::model", "none")));
        now.insert(
            key, found.values().value(key, QCoreApplication::translate("cambench::model", "none")));
    }
    return QCoreApplication::translate("cambench::model",
                                       "another device answers: expected %1, found %2")
        .arg(valuesText(was), valuesText(now));
}

Status checkRestoreTarget(const DeviceIdentity& backup, const DeviceIdentity& found,
                          const ReplacementConsent& consent, const QString& what) {
    if ((backup.known() && backup == found) || consent.accepts(found)) return success();
    if (!backup.known())
        return Error::invalidData(
            QCoreApplication::translate(
                "cambench::model",
                "%1 records no identity of the device it was taken from (a backup older than "
                "that record), so CamBench cannot tell whether the device answering (%2) is that "
                "device. Nothing was written. If it is, or if it replaces that device, confirm "
                "it (on the command line: --replacement).")
                .arg(what, found.text()));
    return Error::invalidData(
        QCoreApplication::translate(
            "cambench::model",
            "%1 was taken from another device: %2 (the backup's device: %3; the device "
            "answering: %4). Nothing was written. Only if this device replaces that one, confirm "
            "it (on the command line: --replacement).")
            .arg(what, anotherDeviceText(backup, found), backup.text(), found.text()));
}

}  // namespace cambench
