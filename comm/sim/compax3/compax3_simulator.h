#pragma once

#include "comm/sim/simulator_registry.h"

namespace cambench::comm {

// The Compax3 simulator: "sim" / "sim:address=5;type=S150V4" ports when the
// PC speaks compax3 or compax3-rs485, and cambench-sim --family compax3
// [--rs485 --address N] [--drive-type T] [--serial S] [--baud B].
SimulatorInfo compax3Simulator();

}  // namespace cambench::comm
