#pragma once

#include "ascii_link.h"

#include "comm/device/protocol_registry.h"
#include "comm/device/protocol_settings.h"

namespace cambench::comm {

// The connection settings of the CamCon ASCII protocol: one class for both
// framings, registered as "standard" (RS232, 9600) and "multiuser" (RS485
// bus, 38400, device numbers 0..63).
class AsciiProtocolSettings : public ProtocolSettings {
public:
    explicit AsciiProtocolSettings(Framing framing = Framing::Standard) { ascii.framing = framing; }
    explicit AsciiProtocolSettings(const AsciiSettings& settings) : ascii(settings) {}

    AsciiSettings ascii;

    QString protocolId() const override;
    std::unique_ptr<ProtocolSettings> clone() const override;
    int device() const override;
    void setDevice(int device) override { ascii.device = device; }
    int timeoutMs() const override { return ascii.timeoutMs; }
    QVariantMap toMap() const override;
    void fromMap(const QVariantMap& map) override;
};

// The device number (0..lastDevice) and the PC's own number (0..63) a
// CamCon bus protocol takes: Multiuser and Cam-BUS.
QList<ProtocolOption> camConBusOptions(int lastDevice);

// "standard" and "multiuser".
QList<ProtocolInfo> camconAsciiProtocols();

}  // namespace cambench::comm
