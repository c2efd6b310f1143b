#pragma once

#include "model/device_identity.h"

#include <QString>

#include <functional>

class QObject;
class QWidget;

namespace cambench {

class DeviceSession;

// Before a restore to a device that is not the one the backup was taken
// from (issue 35: a restore goes only to that device): shows both
// identities value by value, the differing ones marked, and asks whether
// the device answering replaces that one. No is the default; true = the
// person accepts exactly `found` (ReplacementConsent::of(found)).
bool acceptsReplacement(QWidget* parent, const QString& title, const QString& backupName,
                        const DeviceIdentity& backup, const DeviceIdentity& found);

// Reads who the device on `session` is (DeviceConnection::readIdentity)
// on its worker (the answer comes to `context`, the question on `parent`)
// and calls `go` with the person's consent: none when it is the backup's
// own device, the identity found when they accept it as the replacement.
// `go` is not called when they decline, or when the identity cannot be read
// (said on `parent`): `declined` is, with why (a machine's restore goes on
// with its other devices). The restore's use case checks again before its
// first byte, so a device swapped after the question is refused.
void askRestoreTarget(DeviceSession* session, QObject* context, QWidget* parent,
                      const QString& title, const QString& backupName, const DeviceIdentity& backup,
                      std::function<void(const ReplacementConsent&)> go,
                      std::function<void(const QString& why)> declined = {});

}  // namespace cambench
