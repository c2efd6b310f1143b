#pragma once

#include "app/registry/family_parts.h"

namespace cambench {

// Every part of the MICRO DESIGN MC-1 family (see mc1_parts.cpp).
FamilyParts mc1Parts();

}  // namespace cambench
