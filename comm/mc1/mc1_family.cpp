#include "mc1_family.h"

#include "comm/device/family_registry.h"

namespace cambench::comm {

void registerMc1Family(FamilyRegistry& registry) {
    FamilyInfo info;
    info.id = QStringLiteral("mc1");
    info.title = QStringLiteral("MICRO DESIGN MC100/MC200 (MC-1)");
    info.defaultProtocol = QStringLiteral("mc1");
    info.built = false;
    info.notBuilt = QStringLiteral(
        "The MICRO DESIGN MC100/MC200 (MC-1) family is not built into this CamBench yet: no "
        "protocol, simulator or "
        "page of it exists here");
    registry.add(info);
}

}  // namespace cambench::comm
