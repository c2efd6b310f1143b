#pragma once

#include "app/registry/family_parts.h"

namespace cambench {

// Every part of the Parker Compax3 family (see compax3_parts.cpp).
FamilyParts compax3Parts();

}  // namespace cambench
