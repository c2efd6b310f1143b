#include "mc1_family.h"

#include "comm/device/family_registry.h"

namespace cambench::comm {

void registerMc1Family(FamilyRegistry& registry) {
    registry.add(FamilyInfo::announced(QStringLiteral("mc1"),
                                       QStringLiteral("MICRO DESIGN MC100/MC200 (MC-1)"),
                                       QStringLiteral("mc1")));
}

}  // namespace cambench::comm
