#include "mc1_family.h"

#include "comm/device/family_registry.h"

namespace cambench::comm {

void registerMc1Family(FamilyRegistry& registry) {
    FamilyInfo family;
    family.id = QStringLiteral("mc1");
    family.title = QStringLiteral("MICRO DESIGN MC100/MC200 (MC-1)");
    family.defaultProtocol = QStringLiteral("mc1");
    family.built = true;
    registry.add(family);
}

}  // namespace cambench::comm
