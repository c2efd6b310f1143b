#pragma once

// The MC-1's part of `check` (issue 29): the variant probe, the variable
// width, flag and I/O addressing (reads that must agree), the axes RDTABLE
// finds; reading telegrams only (the gate keeps any other off the line).

#include "comm/usecases/device_check.h"

namespace cambench::usecases {

// The MC-1's FamilyCheck (its FamilyParts::checks).
FamilyCheck mc1Check();

}  // namespace cambench::usecases
