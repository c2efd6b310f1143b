#include "slotted_family.h"

#include "fake_family.h"

#include "comm/device/family_registry.h"
#include "comm/device/protocol_registry.h"

namespace cambench::fake {

namespace {

// The slot the line reaches, as every protocol keeps its settings.
class SlottedSettings : public comm::ProtocolSettings {
public:
    QString protocolId() const override { return QStringLiteral("slotted-line"); }
    std::unique_ptr<comm::ProtocolSettings> clone() const override {
        return std::make_unique<SlottedSettings>(*this);
    }
    QVariantMap toMap() const override { return {{QStringLiteral("slot"), m_slot}}; }
    void fromMap(const QVariantMap& map) override {
        m_slot = map.value(QStringLiteral("slot"), m_slot).toInt();
    }

private:
    int m_slot = 1;
};

}  // namespace

FamilyParts slottedParts() {
    FamilyParts parts;
    parts.id = QStringLiteral("slotted");
    parts.family = [] {
        return builtTestFamily(QStringLiteral("Slotted test device"),
                               QStringLiteral("slotted-line"));
    };
    parts.protocols = [] {
        comm::ProtocolInfo protocol = fakeLineProtocol(QStringLiteral("slotted-line"),
                                                       QStringLiteral("Slotted line protocol"));
        protocol.options = {comm::ProtocolOption::number(
            QStringLiteral("slot"), QStringLiteral("slot"), 1, 8, 1, QStringLiteral("Slot:"),
            QStringLiteral("the slot of the rack the device sits in"))};
        protocol.makeSettings = [] { return std::make_unique<SlottedSettings>(); };
        return QList{protocol};
    };
    return parts;
}

}  // namespace cambench::fake
