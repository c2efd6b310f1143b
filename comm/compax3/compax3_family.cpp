#include "compax3_family.h"

#include "comm/device/family_registry.h"

namespace cambench::comm {

void registerCompax3Family(FamilyRegistry& registry) {
    FamilyInfo family;
    family.id = QStringLiteral("compax3");
    family.title = QStringLiteral("Parker Compax3");
    family.defaultProtocol = QStringLiteral("compax3");
    family.built = true;
    registry.add(family);
}

}  // namespace cambench::comm
