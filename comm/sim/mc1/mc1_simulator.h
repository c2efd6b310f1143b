#pragma once

#include "comm/mc1/mc1_variant.h"
#include "comm/sim/simulator_registry.h"

namespace cambench::comm {

// How a simulated MC200's axes and PLC program differ from the default
// (axes 1..8, the parameter numbers CamBench guesses, the UDB at 0x10000).
struct Mc1SimAxes {
    std::optional<QList<int>> axes;        // the logical axes it has
    std::optional<quint16> parameterBase;  // its numbers: base + 0x10 × axis + 0, 1, 2
    // Where its PLC program's data block starts (SYSDATA 08): it moves with
    // the program loaded, so two controllers with other programs differ.
    std::optional<quint32> udbAddress;
};

// A simulated MC100/MC200 of `variant` on its line at `baud`, with demo
// values (variables, flags, outputs) so that a first look shows something;
// `syncMs` 5 or 10: an MC100MA single-FIFO card's 0xFF synchronisation.
SimulatedLine mc1SimulatedLine(Mc1Variant variant, int baud, const SimHostOptions& shared,
                               int syncMs = 0, const Mc1SimAxes& axes = {});

// A simulated MC100 that speaks its ASCII protocol ("mc1-ascii").
SimulatedLine mc1AsciiSimulatedLine(int baud, const SimHostOptions& shared);

// The MC-1 simulator: "sim" / "sim:variant=mc100v1;sync=10" /
// "sim:axes=1,3;parameters=0x2000;udb=0x12000" ports when the PC speaks
// mc1, and cambench-sim --family mc1 [--variant V] [--sync MS] [--baud B]
// [--axes 1,3] [--parameter-base 0x2000] [--udb 0x12000].
SimulatorInfo mc1Simulator();

}  // namespace cambench::comm
