#pragma once

#include "sim_camcon_endpoint.h"
#include "sim_port_config.h"
#include "sim_profile.h"

#include <memory>

namespace cambench::comm {

class SimDevice;
class SimEndpoint;
class SimLine;

// A plausible machine to show and test with: a few programs with named
// outputs and cams (one wrapping through zero), dead times, two users and
// a couple of PLC networks.
void loadDemoState(SimDevice& device);

// Replaces every cam by `camsPerTrack` evenly spaced cams on every output of
// every program, for benchmarks (8 per track on the default profile make a
// backup of more than 32 KiB).
void fillBenchmarkCams(SimDevice& device, int camsPerTrack);

// Replaces the users by `count` users "User 01" (number 1001), "User 02", ...
// (at most the profile's maxUsers), for lists long enough to walk.
void fillUsers(SimDevice& device, int count);

// An ASCII line with the configured devices (demo or benchmark state) and faults.
std::unique_ptr<SimLine> makeSimLine(const SimPortConfig& config, const SimProfile& profile = {});
// The line `config` describes: ASCII (makeSimLine) or, with a table
// variant, a 3964R line to one device in the same demo or benchmark state.
std::unique_ptr<SimCamConEndpoint> makeSimEndpoint(const SimPortConfig& config,
                                                   const SimProfile& profile = {});

}  // namespace cambench::comm
