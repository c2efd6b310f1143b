#pragma once

#include "motion_control.h"
#include "progress.h"

#include "comm/engine/request_engine.h"
#include "model/device_identity.h"
#include "model/result.h"

#include <QCoreApplication>
#include <QList>

#include <QString>

namespace cambench::comm {

// One open connection to a device of some family through one protocol, as
// the worker thread holds it. A family's interface (CamConDevice, later the
// MC-1 and Compax3 ones) derives from this; jobs ask the JobContext for the
// family they are written for.
class DeviceConnection {
public:
    virtual ~DeviceConnection() = default;

    // "camcon", "mc1", "compax3"
    virtual QString familyId() const = 0;
    // The protocol registry id: "standard", "multiuser", "3964r-n96", ...
    virtual QString protocolId() const = 0;
    // The engine under it: cancel flag, traffic sink, counters.
    virtual RequestEngine& engine() = 0;
    // What answers on the line, in one line for a person ("CamCon, EPROM
    // 11.10.1994, device 0, 32 outputs"), read with queries only: Detect
    // sends it to a device it does not know yet. Fails when nothing of this
    // family answers.
    virtual Result<QString> identify() = 0;
    // What tells this device apart from others of its family
    // (model/device_identity.h), read with queries only: what a restore
    // compares with its backup's and a machine with its file's. A family
    // that knows nothing better records what identify() says.
    virtual Result<DeviceIdentity> readIdentity() {
        const Result<QString> text = identify();
        if (!text) return text.error();
        DeviceIdentity identity;
        identity.set(QStringLiteral("device"), *text);
        return identity;
    }
    // identify() as a quick probe of a line that may hold anything: no
    // retries, the shortest waits the protocol allows. The connection is
    // used for nothing else afterwards.
    virtual Result<QString> probe() {
        EngineSettings quick = engine().settings();
        quick.retries = 0;
        engine().setSettings(quick);
        return identify();
    }
    // Device numbers in [first,last] that answer on a bus (ProtocolInfo::
    // isBus); a point-to-point protocol has none to scan.
    virtual Result<QList<int>> scanBus(int first, int last, const ProgressFn& progress = {}) {
        Q_UNUSED(first);
        Q_UNUSED(last);
        Q_UNUSED(progress);
        return Error::usage(
            QCoreApplication::translate("cambench::comm", "this protocol has no bus to scan"));
    }
    // A bus protocol addresses later requests to `device`; others ignore it.
    virtual void setDevice(int device) { Q_UNUSED(device); }
    // The device's motion (axes, a drive) when its family can move
    // something; nullptr when it cannot.
    virtual MotionControl* motionControl() { return nullptr; }
};

}  // namespace cambench::comm
