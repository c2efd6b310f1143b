#pragma once

#include "sim_output.h"

#include <QByteArrayView>
#include <QList>
#include <QString>

namespace cambench::comm {

// The far end of a simulated line: what the simulated devices make of the
// bytes the PC sends, as replies with the time each waits before it leaves.
// One per protocol and family (the CamCon's: SimLine, SimTableLine).
// The transports (in-process, pty, TCP) pace the replies at the baud rate
// and call poll() for the devices' own timers.
class SimEndpoint {
public:
    virtual ~SimEndpoint() = default;

    // Bytes from the PC, at `nowMs` of a monotonic clock.
    virtual QList<SimOutput> receive(QByteArrayView bytes, qint64 nowMs) = 0;
    // Time has passed: the devices' own timers (a 3964R acknowledgement).
    virtual QList<SimOutput> poll(qint64 nowMs) {
        Q_UNUSED(nowMs);
        return {};
    }
    // When poll() wants to run next; -1 = no timer.
    virtual qint64 nextTimerMs() const { return -1; }
    // "Standard", "Multiuser", "3964R n96": for descriptions.
    virtual QString protocolName() const = 0;
};

}  // namespace cambench::comm
