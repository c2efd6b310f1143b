#pragma once

#include "../camcon_fixture.h"

#include "comm/sim/camcon/sim_demo.h"
#include "comm/sim/camcon/sim_line.h"
#include "comm/sim/sim_pacer.h"
#include "comm/sim/sim_pty_server.h"

#include <QList>

#include <memory>

namespace cambench::test {

// The simulated CamCon (demo state) served on a pseudo-terminal in the test
// process: the GUI reaches it through the real QSerialPort, while the test
// sees the device's state and every command it received, makes it refuse a
// command, fall silent, or pulls the cable.
class PtySimulator {
public:
    // More than one device number: a Multiuser line.
    explicit PtySimulator(bool throttle = false, int baud = 9600, const QList<int>& devices = {0}) {
        comm::SimPortConfig config;
        config.devices = devices;
        config.baud = baud;
        config.throttle = throttle;
        m_line = comm::makeSimLine(config);
        m_pacer = std::make_unique<comm::SimPacer>(baud, throttle);
        m_server = std::make_unique<comm::SimPtyServer>(*m_line, *m_pacer);
        m_open = m_server->open().ok();
        m_path = m_server->slavePath();
        m_line->injections().setLogging(true);
    }

    bool isOpen() const { return m_open; }
    QString path() const { return m_path; }
    comm::SimLine& line() { return *m_line; }
    comm::SimDevice& device(int number = 0) { return *m_line->device(number); }
    comm::SimInjections& injections() { return m_line->injections(); }

    // Commands ('!') the device received since the log was last cleared.
    int commandsReceived() const { return m_line->injections().commands(); }
    // The device's cams of `output` (1-based) in `program`.
    QList<Cam> track(int program, int output, int number = 0) {
        return device(number).state().cams.track(program, output - 1);
    }

    // The device stops answering (a cable pulled at the device's end).
    void fallSilent(bool silent = true) { injections().setDead(0, silent); }
    // The simulator goes away (the adapter pulled): the PC's port fails.
    void stop() { m_server.reset(); }

private:
    std::unique_ptr<comm::SimLine> m_line;
    std::unique_ptr<comm::SimPacer> m_pacer;
    std::unique_ptr<comm::SimPtyServer> m_server;
    bool m_open = false;
    QString m_path;
};

// The GUI started on `sim` through the real QSerialPort, identity and the
// first reads done; null when the simulator or the start failed.
inline std::unique_ptr<Shell> startOnPty(PtySimulator& sim) {
    return sim.isOpen() ? startOnSimulator(sim.path()) : nullptr;
}

}  // namespace cambench::test
