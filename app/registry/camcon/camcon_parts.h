#pragma once

#include "app/registry/family_parts.h"

namespace cambench {

// Every part of the Digitronic CamCon family (see camcon_parts.cpp).
FamilyParts camconParts();

}  // namespace cambench
