#pragma once

// A second family that exists only in the tests (issue 38, item 1): one
// protocol, "slotted-line", with a connection option of its own, "slot"
// (1..8, default 1), declared once in its ProtocolInfo. The command line
// (--slot), a machine file ("slot": 3) and the connection page (a field)
// take it without a line of the shell naming it.

#include "app/registry/family_parts.h"

namespace cambench::fake {

// The family and its protocol (it reaches the fake family's device).
FamilyParts slottedParts();

}  // namespace cambench::fake
