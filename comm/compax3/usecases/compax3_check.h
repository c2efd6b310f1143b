#pragma once

// The Compax3's part of `check` (issue 29): the info string, both object
// separators ('.' and ','), '$' answers, each dictionary object's presence
// and type, the refusal numbers; reading requests only (the gate keeps
// writes and functions off the line).

#include "comm/usecases/device_check.h"

namespace cambench::usecases {

// The Compax3's FamilyCheck (its FamilyParts::checks).
FamilyCheck compax3Check();

}  // namespace cambench::usecases
