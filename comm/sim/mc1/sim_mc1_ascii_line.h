#pragma once

#include "sim_mc1_controller.h"

#include "comm/sim/sim_endpoint.h"
#include "comm/sim/sim_faults.h"

namespace cambench::comm {

// A simulated MC100 set to its ASCII protocol: each CR-ended line is one
// request (docs/protocols/mc1.md, "ASCII"); the answer is the value, 1 or 0,
// OK, or ERR for anything it refuses (a line it cannot read, a number it
// lacks, a value out of 24 bits, an input written).
class SimMc1AsciiLine : public SimEndpoint {
public:
    explicit SimMc1AsciiLine(const SimFaultSettings& faults = {})
        : m_controller(Mc1Variant::Mc100V1), m_faults(faults) {}

    SimMc1Controller& controller() { return m_controller; }
    QList<SimOutput> receive(QByteArrayView bytes, qint64 nowMs) override;
    QString protocolName() const override { return QStringLiteral("MC100 ASCII"); }

private:
    QByteArray answer(const QByteArray& line);

    SimMc1Controller m_controller;
    SimFaults m_faults;
    QByteArray m_pending;
};

}  // namespace cambench::comm
