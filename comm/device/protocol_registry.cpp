#include "protocol_registry.h"

#include <QStringList>

namespace cambench::comm {

ProtocolRegistry& ProtocolRegistry::instance() {
    static ProtocolRegistry registry;
    return registry;
}

void ProtocolRegistry::add(ProtocolInfo info) {
    for (auto& existing : m_protocols) {
        if (existing->id == info.id) {
            *existing = std::move(info);  // registering again replaces
            return;
        }
    }
    m_protocols.append(std::make_shared<ProtocolInfo>(std::move(info)));
}

const ProtocolInfo* ProtocolRegistry::find(const QString& id) const {
    for (const auto& info : m_protocols)
        if (info->id.compare(id, Qt::CaseInsensitive) == 0) return info.get();
    return nullptr;
}

QList<const ProtocolInfo*> ProtocolRegistry::all() const {
    QList<const ProtocolInfo*> list;
    for (const auto& info : m_protocols) list.append(info.get());
    return list;
}

QString ProtocolRegistry::idList() const {
    QStringList ids;
    for (const auto& info : m_protocols) ids.append(info->id);
    return ids.join(QStringLiteral(", "));
}

LineTiming lineTimingFor(const SerialSettings& serial) {
    LineTiming line;
    line.baud = serial.baud;
    const int parity = serial.parity == 'N' ? 0 : 1;
    const int stop = serial.stopBits == 1 ? 1 : 2;
    line.bitsPerByte = 1 + serial.dataBits + parity + stop;
    return line;
}

}  // namespace cambench::comm
