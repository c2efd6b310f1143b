#include "camcon_family.h"

#include "comm/device/family_registry.h"

namespace cambench::comm {

FamilyInfo camconFamily() {
    FamilyInfo family;
    family.title = QStringLiteral("Digitronic CamCon");
    family.defaultProtocol = QStringLiteral("standard");
    family.built = true;
    return family;
}

}  // namespace cambench::comm
