#pragma once

#include "table_link.h"

#include "comm/device/protocol_registry.h"
#include "comm/device/protocol_settings.h"

namespace cambench::comm {

// The connection settings of the CamCon table interface: the RK512 variant
// (its registry id) and the link's patience. Registered as "3964r-n96"
// (9600 8N1, 32-bit word offsets) and "3964r-e38" (38400 8E1, 16-bit word
// offsets). Point to point: no device number.
class TableProtocolSettings : public ProtocolSettings {
public:
    explicit TableProtocolSettings(table::Rk512Variant variant = table::Rk512Variant::N96) {
        table.variant = variant;
    }

    table::TableSettings table;

    QString protocolId() const override;
    std::unique_ptr<ProtocolSettings> clone() const override;
    int timeoutMs() const override { return table.timeoutMs; }
    QVariantMap toMap() const override;
    void fromMap(const QVariantMap& map) override;
};

// The registry id of a variant: "3964r-n96", "3964r-e38".
QString tableProtocolId(table::Rk512Variant variant);

// "3964r-n96" and "3964r-e38".
QList<ProtocolInfo> camconTableProtocols();

}  // namespace cambench::comm
