#pragma once

#include "sim_compax3_drive.h"

#include "comm/sim/sim_endpoint.h"
#include "comm/sim/sim_faults.h"

#include <memory>

namespace cambench::comm {

// A Compax3 on its line: RS232 (no address: every line is for it) or RS485
// (a line starts with the drive's address 0..99; other addresses are
// someone else's and get no answer; every answer starts with '*').
class SimCompax3Line : public SimEndpoint {
public:
    // `address` -1: RS232.
    SimCompax3Line(int address, SimCompax3Drive drive, const SimFaultSettings& faults = {})
        : m_address(address), m_drive(std::move(drive)), m_faults(faults) {}

    SimCompax3Drive& drive() { return m_drive; }
    // A simulated machine: the drive's axis drives `shaft` from now on.
    void driveShaft(std::shared_ptr<SimShaft> shaft);
    QList<SimOutput> receive(QByteArrayView bytes, qint64 nowMs) override;
    // Tests: every later answer comes `ms` late (a slow drive, a gateway),
    // on top of the faults' own delay.
    void delayAnswers(int ms) { m_delayMs = ms; }
    QString protocolName() const override;

private:
    int m_address;
    SimCompax3Drive m_drive;
    SimFaults m_faults;
    QByteArray m_pending;
    int m_delayMs = 0;
    std::unique_ptr<SimShaftDriver> m_shaft;
};

}  // namespace cambench::comm
