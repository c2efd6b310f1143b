#pragma once

#include "mc1_controller.h"

#include "comm/device/protocol_registry.h"
#include "comm/device/protocol_settings.h"

namespace cambench::comm {

// The connection settings of the MC-1 protocol ("mc1"): the variant
// ("auto" probes it) and the user's fixed timeout.
class Mc1ProtocolSettings : public ProtocolSettings {
public:
    Mc1Settings mc1;

    QString protocolId() const override { return QStringLiteral("mc1"); }
    std::unique_ptr<ProtocolSettings> clone() const override;
    int timeoutMs() const override { return mc1.timeoutMs; }
    QStringList variantKeys() const override;
    QVariantMap toMap() const override;
    void fromMap(const QVariantMap& map) override;
};

// Adds "mc1" (RS232, 9600 8N1, DTR high and RTS low: they power an MC200's
// interface) to `registry`.
void registerMc1Protocol(ProtocolRegistry& registry);

}  // namespace cambench::comm
