#pragma once

#include "comm/engine/request_engine.h"

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
    // A bus protocol addresses later requests to `device`; others ignore it.
    virtual void setDevice(int device) { Q_UNUSED(device); }
};

}  // namespace cambench::comm
