#include "compax3_family.h"

#include "comm/device/family_registry.h"

namespace cambench::comm {

FamilyInfo compax3Family() {
    FamilyInfo family;
    family.title = QStringLiteral("Parker Compax3");
    family.defaultProtocol = QStringLiteral("compax3");
    family.built = true;
    return family;
}

}  // namespace cambench::comm
