#pragma once

#include "model/result.h"

#include <functional>

class QWidget;

namespace cambench {

class DeviceSession;
class Workspace;

// Which device answers, asked on every connect and reconnect (a typed
// port, a reconnect to the same TCP address, another Multiuser device
// number can each reach another device). Reads the identity and the cheap
// fingerprint (programmed and free cams, programmed dead times) and, when
// they are not those the workspace's device copies were read from, forgets
// every device copy: nothing read from the old device is shown, written,
// compared or saved as this device's state. Sections this protocol lacks
// lose their device copy too. The new identity goes to the panel, title and
// banner; the session counts as checked afterwards (writes wait for it).
// `done` gets whether another device answers.
using DeviceCheckDone = std::function<void(const Status& status, bool otherDevice)>;
quint64 checkConnectedDevice(QWidget* context, DeviceSession* session, Workspace* workspace,
                             DeviceCheckDone done);

}  // namespace cambench
