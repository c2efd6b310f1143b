#pragma once

#include "sim_port_config.h"

#include "comm/sim/simulator_registry.h"
#include "comm/transport/transport.h"

#include <memory>

namespace cambench::comm {

// The simulated CamCon line `config` describes, paced at its baud rate.
SimulatedLine camConSimulatedLine(const SimPortConfig& config);

// The CamCon simulator behind a "sim" port (see parseSimPort): the device
// speaks `protocol` (a registry id) unless the port names a framing.
Result<std::unique_ptr<Transport>> makeCamConSimTransport(const QString& port,
                                                          const SerialSettings& serial,
                                                          const QString& protocol = {});

// The CamCon simulator: "sim" ports and cambench-sim --family camcon.
SimulatorInfo camconSimulator();

}  // namespace cambench::comm
