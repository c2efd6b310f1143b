#include "camcon_family.h"

#include "comm/device/family_registry.h"

namespace cambench::comm {

void registerCamConFamily(FamilyRegistry& registry) {
    FamilyInfo info;
    info.id = QStringLiteral("camcon");
    info.title = QStringLiteral("Digitronic CamCon");
    info.defaultProtocol = QStringLiteral("standard");
    info.built = true;
    registry.add(info);
}

}  // namespace cambench::comm
