#pragma once

#include "mc1_ascii_controller.h"
#include "mc1_controller.h"

#include "comm/device/protocol_registry.h"
#include "comm/device/protocol_settings.h"

namespace cambench::comm {

// The connection settings of the MC-1 protocol ("mc1"): the variant
// ("auto" probes it), the user's fixed timeout and the axes ("axes": ""
// finds them with RDTABLE, "1,2" uses those).
class Mc1ProtocolSettings : public ProtocolSettings {
public:
    Mc1Settings mc1;

    QString protocolId() const override { return QStringLiteral("mc1"); }
    std::unique_ptr<ProtocolSettings> clone() const override;
    int timeoutMs() const override { return mc1.timeoutMs; }
    // The variants it can be told to expect ("auto" first: probe), the
    // words of its "variant" option.
    static QStringList variantKeys();
    QVariantMap toMap() const override;
    void fromMap(const QVariantMap& map) override;
};

// The MC100's ASCII protocol ("mc1-ascii"): only the user's timeout.
class Mc1AsciiProtocolSettings : public ProtocolSettings {
public:
    int timeout = 0;

    QString protocolId() const override { return QStringLiteral("mc1-ascii"); }
    std::unique_ptr<ProtocolSettings> clone() const override;
    int timeoutMs() const override { return timeout; }
    QVariantMap toMap() const override;
    void fromMap(const QVariantMap& map) override;
};

// The family's protocols: "mc1", the binary MC-1 (RS232, 9600 8N1, DTR
// high and RTS low: they power an MC200's interface), and "mc1-ascii", the
// MC100's ASCII protocol.
QList<ProtocolInfo> mc1Protocols();

}  // namespace cambench::comm
