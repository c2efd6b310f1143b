#include "compax3_family.h"

#include "comm/device/family_registry.h"

namespace cambench::comm {

void registerCompax3Family(FamilyRegistry& registry) {
    FamilyInfo info;
    info.id = QStringLiteral("compax3");
    info.title = QStringLiteral("Parker Compax3");
    info.defaultProtocol = QStringLiteral("compax3-ascii");
    info.built = false;
    info.notBuilt = QStringLiteral(
        "The Parker Compax3 family is not built into this CamBench yet: no protocol, simulator or "
        "page of it exists here");
    registry.add(info);
}

}  // namespace cambench::comm
