#include "compax3_family.h"

#include "comm/device/family_registry.h"

namespace cambench::comm {

void registerCompax3Family(FamilyRegistry& registry) {
    registry.add(FamilyInfo::announced(QStringLiteral("compax3"), QStringLiteral("Parker Compax3"),
                                       QStringLiteral("compax3-ascii")));
}

}  // namespace cambench::comm
