#include "family_pages.h"

#include "device_session.h"

#include "comm/device/protocol_registry.h"

namespace cambench {

FamilyPageRegistry& FamilyPageRegistry::instance() {
    static FamilyPageRegistry registry;
    return registry;
}

void FamilyPageRegistry::add(FamilyPage page) {
    m_pages.append(std::move(page));
}

QString sessionFamily(const DeviceSession& session) {
    const comm::ProtocolInfo* info =
        comm::ProtocolRegistry::instance().find(session.protocol().protocolId());
    return info ? info->familyId : QString();
}

}  // namespace cambench
