#pragma once

#include "sim_mc1_controller.h"

#include "comm/sim/sim_endpoint.h"
#include "comm/sim/sim_faults.h"

#include <memory>

namespace cambench::comm {

// One simulated MC100/MC200 on its RS232 line: bytes collect until a whole
// telegram is there, then the controller answers. A first byte that starts
// no telegram of its variant, or a telegram that stops for longer than the
// character timeout (100 ms, as the manufacturer's emulator), is NAKed and
// dropped, as the real one does. Faults: an ignored telegram is neither
// executed nor answered; a dropped answer was executed.
class SimMc1Line : public SimEndpoint {
public:
    explicit SimMc1Line(Mc1Variant variant, const SimFaultSettings& faults = {})
        : m_controller(variant), m_faults(faults) {}

    SimMc1Controller& controller() { return m_controller; }
    // A simulated machine: logical axis `axis` drives `shaft` from now on;
    // a Usage error when the controller lacks it.
    Status driveShaft(std::shared_ptr<SimShaft> shaft, int axis);
    const SimFaults& faults() const { return m_faults; }
    // An MC100MA single-FIFO card: 0xFF every `periodMs` (5 or 10; 0 off),
    // and a telegram is taken only when its first byte comes within 2 or
    // 4 ms after one (each 0xFF opens one window); others are lost silently.
    void setSync(int periodMs);
    int telegramsOutsideWindow() const { return m_outsideWindow; }
    QList<SimOutput> receive(QByteArrayView bytes, qint64 nowMs) override;
    QList<SimOutput> poll(qint64 nowMs) override;
    qint64 nextTimerMs() const override;
    QString protocolName() const override;

private:
    SimMc1Controller m_controller;
    SimFaults m_faults;
    QByteArray m_pending;
    qint64 m_deadline = -1;
    int m_syncPeriod = 0;
    qint64 m_nextSync = -1;
    qint64 m_lastSync = -1;
    bool m_windowOpen = false;
    int m_outsideWindow = 0;
    std::unique_ptr<SimShaftDriver> m_shaft;
    int m_shaftAxis = 1;
};

}  // namespace cambench::comm
