#pragma once

#include "comm/camcon/ascii/ascii_camcon.h"
#include "comm/camcon/ascii/ascii_link.h"
#include "comm/sim/camcon/camcon_simulator.h"
#include "comm/sim/camcon/sim_line.h"
#include "comm/sim/sim_transport.h"

#include <memory>
#include <optional>

namespace cambench::tests {

// The in-process simulator (demo state) with the ASCII CamCon on top; bytes
// arrive at once. The simulator logs every command its devices receive.
struct SimBench {
    explicit SimBench(QList<int> devices = {0}, std::optional<comm::Framing> framing = {});
    // Another device than the demo's (config.outputs, config.epromDate);
    // bytes arrive at once whatever config.throttle says.
    explicit SimBench(comm::SimPortConfig config);

    // The bench always builds an ASCII line (see the constructor).
    comm::SimLine& line() { return dynamic_cast<comm::SimLine&>(transport->line()); }
    comm::SimDevice& device(int number = 0) { return *line().device(number); }
    comm::SimInjections& injections() { return line().injections(); }
    DeviceInfo info();

    // Commands ('!') the devices received since the last call.
    int commandsSent();

    std::unique_ptr<comm::SimTransport> transport;
    std::unique_ptr<comm::AsciiLink> link;
    std::unique_ptr<comm::AsciiCamCon> client;
};

}  // namespace cambench::tests
