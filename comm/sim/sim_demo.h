#pragma once

#include "sim_port_config.h"
#include "sim_profile.h"

#include <memory>

namespace cambench::comm {

class SimDevice;
class SimLine;

// A plausible machine to show and test with: a few programs with named
// outputs and cams (one wrapping through zero), dead times, two users and
// a couple of PLC networks.
void loadDemoState(SimDevice& device);

// Replaces every cam by `camsPerTrack` evenly spaced cams on every output of
// every program, for benchmarks (8 per track on the default profile make a
// backup of more than 32 KiB).
void fillBenchmarkCams(SimDevice& device, int camsPerTrack);

// A line with the configured devices (demo or benchmark state) and faults.
std::unique_ptr<SimLine> makeSimLine(const SimPortConfig& config, const SimProfile& profile = {});

}  // namespace cambench::comm
