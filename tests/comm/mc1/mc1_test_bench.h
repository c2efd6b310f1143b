#pragma once

// A simulated MC100/MC200 behind a real Mc1Controller and request engine,
// for the MC-1 device tests.
#include "comm/mc1/mc1_controller.h"
#include "comm/sim/mc1/mc1_simulator.h"
#include "comm/sim/mc1/sim_mc1_line.h"
#include "comm/sim/sim_transport.h"

#include <QElapsedTimer>

namespace cambench::comm {

// A simulated controller of `variant` (its axes as `axes` says) behind an
// Mc1Controller told `given` (none: probe).
struct Mc1TestBench {
    explicit Mc1TestBench(Mc1Variant variant, std::optional<Mc1Variant> given = std::nullopt,
                          const SimFaultSettings& faults = {}, int syncMs = 0,
                          const Mc1SimAxes& axes = {})
        : transport(line(variant, faults, syncMs, axes)),
          controller(transport, settings(given), timing()) {
        (void)transport.open();
    }
    static SimulatedLine line(Mc1Variant variant, const SimFaultSettings& faults, int syncMs,
                              const Mc1SimAxes& axes) {
        SimHostOptions shared;
        shared.throttle = false;
        shared.faults = faults;
        return mc1SimulatedLine(variant, 115200, shared, syncMs, axes);
    }
    SimMc1Line& simLine() { return static_cast<SimMc1Line&>(transport.line()); }
    static Mc1Settings settings(std::optional<Mc1Variant> given) {
        Mc1Settings s;
        s.variant = given;
        return s;
    }
    static LineTiming timing() {
        LineTiming t;
        t.baud = 115200;
        return t;
    }
    SimMc1Controller& sim() { return static_cast<SimMc1Line&>(transport.line()).controller(); }
    qint64 simNow() const { return clock.elapsed(); }

    SimTransport transport;
    Mc1Controller controller;
    Mc1Device& device = controller;  // as jobs see it (with its default arguments)
    QElapsedTimer clock;
};

}  // namespace cambench::comm
