#pragma once

#include "comm/device/protocol_registry.h"
#include "comm/device/protocol_settings.h"

namespace cambench::comm {

// The connection settings of a Compax3: the drive's RS485 address (the
// "compax3-rs485" protocol; RS232 has none) and the user's fixed timeout.
class Compax3ProtocolSettings : public ProtocolSettings {
public:
    explicit Compax3ProtocolSettings(bool rs485) : m_rs485(rs485) {}

    int address = 0;  // 0..99
    int timeout = 0;

    QString protocolId() const override;
    std::unique_ptr<ProtocolSettings> clone() const override;
    int device() const override { return m_rs485 ? address : -1; }
    void setDevice(int device) override { address = qBound(0, device, 99); }
    int timeoutMs() const override { return timeout; }
    QVariantMap toMap() const override;
    void fromMap(const QVariantMap& map) override;

private:
    bool m_rs485;
};

// "compax3" (RS232, no address) and "compax3-rs485" (addresses 0..99):
// both 115200 8N1 with RTS/CTS by default.
QList<ProtocolInfo> compax3Protocols();

}  // namespace cambench::comm
