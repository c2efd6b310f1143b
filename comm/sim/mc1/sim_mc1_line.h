#pragma once

#include "sim_mc1_controller.h"

#include "comm/sim/sim_endpoint.h"

namespace cambench::comm {

// One simulated MC100/MC200 on its RS232 line: bytes collect until a whole
// telegram is there, then the controller answers. A first byte that starts
// no telegram of its variant, or a telegram that stops for longer than the
// character timeout (100 ms, as the manufacturer's emulator), is NAKed and
// dropped, as the real one does.
class SimMc1Line : public SimEndpoint {
public:
    explicit SimMc1Line(Mc1Variant variant) : m_controller(variant) {}

    SimMc1Controller& controller() { return m_controller; }
    QList<SimOutput> receive(QByteArrayView bytes, qint64 nowMs) override;
    QList<SimOutput> poll(qint64 nowMs) override;
    qint64 nextTimerMs() const override { return m_pending.isEmpty() ? -1 : m_deadline; }
    QString protocolName() const override;

private:
    SimMc1Controller m_controller;
    QByteArray m_pending;
    qint64 m_deadline = -1;
};

}  // namespace cambench::comm
