#pragma once

// Who a device is, for "a restore goes only to the device it was taken
// from" (issue 35) and "always the right devices" (issue 36): each family
// says what tells two of its devices apart (a Compax3's serial number and
// type, a CamCon's EPROM date and capacities, an MC-1's variant and what
// its PLC program and axes leave), backups and machine files record it, and
// restore, status and verify compare it with the device that answers.

#include "model/result.h"

#include <QJsonObject>
#include <QMap>
#include <QString>
#include <QStringList>

#include <optional>

namespace cambench {

// Named values, in key order. The keys are file keys, English and never
// translated ("serial", "type"); no value changes by itself or by a write of
// the device's content. Empty: not known (a backup older than the record).
class DeviceIdentity {
public:
    void set(const QString& key, const QString& value) { m_values.insert(key, value); }
    QString value(const QString& key) const { return m_values.value(key); }
    const QMap<QString, QString>& values() const { return m_values; }
    bool known() const { return !m_values.isEmpty(); }

    // "serial C3-4711-0815, type S025V2"; "not recorded" when not known.
    QString text() const;
    // {"serial": "C3-4711-0815", "type": "S025V2"}
    QJsonObject toJson() const;
    // `where` names the object in messages ("device 2 (feed): identity").
    static Result<DeviceIdentity> fromJson(const QJsonValue& value, const QString& where);

    friend bool operator==(const DeviceIdentity& a, const DeviceIdentity& b) {
        return a.m_values == b.m_values;
    }
    friend bool operator!=(const DeviceIdentity& a, const DeviceIdentity& b) { return !(a == b); }

private:
    QMap<QString, QString> m_values;
};

// "another device answers: expected serial C3-1, found serial C3-2": the
// values that differ, on both sides (a value one side lacks as "none").
QString anotherDeviceText(const DeviceIdentity& expected, const DeviceIdentity& found);

// Whether the person accepted the device that answers in place of the one a
// backup was taken from: the command line's --replacement accepts whatever
// answers; the GUI's question accepts exactly the identity it showed, so a
// device swapped after the question is refused again.
struct ReplacementConsent {
    bool anyDevice = false;
    std::optional<DeviceIdentity> device;

    bool accepts(const DeviceIdentity& found) const {
        return anyDevice || (device && *device == found);
    }
    static ReplacementConsent any() { return {true, std::nullopt}; }
    static ReplacementConsent of(const DeviceIdentity& found) { return {false, found}; }
};

// Whether `backup` (what `what` names: a file) may go to the device that
// answers as `found`: success when it is the same device or the person
// accepted it. Otherwise InvalidData, saying both identities, that nothing
// was written and how to accept a replacement; a backup that records no
// identity (older than the record) is refused the same way, since it cannot
// be told whether this device is its own. Run before the first byte is
// written.
Status checkRestoreTarget(const DeviceIdentity& backup, const DeviceIdentity& found,
                          const ReplacementConsent& consent, const QString& what);

}  // namespace cambench
