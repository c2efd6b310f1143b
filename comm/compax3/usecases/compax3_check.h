#pragma once

// The Compax3's part of `check` (issue 29): the info string, both object
// separators ('.' and ','), '$' answers, each dictionary object's presence
// and type, the refusal numbers; reading requests only (the gate keeps
// writes and functions off the line).

#include "comm/usecases/device_check.h"

namespace cambench::usecases {

// Registers the Compax3's FamilyCheck (app/registry, one line).
void registerCompax3Check(CheckRegistry& registry);

}  // namespace cambench::usecases
