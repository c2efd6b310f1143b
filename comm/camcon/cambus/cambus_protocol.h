#pragma once

#include "cambus_view.h"

#include "comm/camcon/ascii/ascii_link.h"
#include "comm/device/protocol_registry.h"
#include "comm/device/protocol_settings.h"

namespace cambench::comm {

// The connection settings of a CamCon on the Cam-BUS: the device asked, the
// PC's own number on the bus (default 63), the link's patience, and the
// monitor through which the GUI's bus view sees what the PC hears (the
// process-wide one unless a test gives its own).
class CamBusProtocolSettings : public ProtocolSettings {
public:
    CamBusProtocolSettings();

    AsciiSettings ascii;  // device, pcNumber, timeoutMs, retries (framing: none of its own)
    CamBusMonitorPtr monitor = CamBusMonitor::shared();

    QString protocolId() const override;
    std::unique_ptr<ProtocolSettings> clone() const override;
    int device() const override { return ascii.device; }
    void setDevice(int device) override { ascii.device = device; }
    int timeoutMs() const override { return ascii.timeoutMs; }
    QVariantMap toMap() const override;
    void fromMap(const QVariantMap& map) override;
};

// "cambus".
ProtocolInfo camconCamBusProtocol();

}  // namespace cambench::comm
