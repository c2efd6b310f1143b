#include "protocol_settings_widget.h"

namespace cambench {

ProtocolWidgetRegistry& ProtocolWidgetRegistry::instance() {
    static ProtocolWidgetRegistry registry;
    return registry;
}

void ProtocolWidgetRegistry::add(const QString& protocolId, Factory factory) {
    m_factories.insert(protocolId, std::move(factory));
}

ProtocolSettingsWidget* ProtocolWidgetRegistry::create(const QString& protocolId) const {
    const auto factory = m_factories.constFind(protocolId);
    return factory == m_factories.cend() ? nullptr : (*factory)(protocolId);
}

}  // namespace cambench
