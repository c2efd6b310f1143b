#pragma once

// The CamCon's part of `check` (issue 29): every reading query of the ASCII
// catalogue, every readable word run of the table map, the Multiuser block
// numbering and the Cam-BUS token timing, each tried on the device with
// reading requests only (the gate below keeps anything else off the line).

#include "comm/usecases/device_check.h"

namespace cambench::usecases {

// The CamCon's FamilyCheck (its FamilyParts::checks).
FamilyCheck camconCheck();

}  // namespace cambench::usecases
