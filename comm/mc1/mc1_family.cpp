#include "mc1_family.h"

#include "comm/device/family_registry.h"

namespace cambench::comm {

FamilyInfo mc1Family() {
    FamilyInfo family;
    family.title = QStringLiteral("MICRO DESIGN MC100/MC200 (MC-1)");
    family.defaultProtocol = QStringLiteral("mc1");
    family.built = true;
    return family;
}

}  // namespace cambench::comm
