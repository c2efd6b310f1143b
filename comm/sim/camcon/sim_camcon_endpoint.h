#pragma once

#include "comm/sim/sim_endpoint.h"

namespace cambench::comm {

class SimDevice;

// A simulated CamCon line (ASCII or 3964R): the host's endpoint whose
// devices a test or benchmark can look into.
class SimCamConEndpoint : public SimEndpoint {
public:
    // The device with this number (a point-to-point line: its one device),
    // or nullptr.
    virtual SimDevice* device(int number) const = 0;
};

}  // namespace cambench::comm
