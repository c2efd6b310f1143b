#pragma once

#include "sim_endpoint.h"
#include "sim_pacer.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <functional>

namespace cambench::comm {

// Event-loop side of the pacing for cambench-sim's endpoints: feeds what the
// PC sent into the line, runs the line's timers, and hands the reply bytes
// to `write` when the pacer says they are on the wire.
class SimReplyScheduler : public QObject {
    Q_OBJECT

public:
    using WriteFn = std::function<void(const QByteArray&)>;

    SimReplyScheduler(SimEndpoint& line, const SimPacer& pacer, WriteFn write,
                      QObject* parent = nullptr);

    void received(const QByteArray& bytes);
    // A new client: forget replies to the old one.
    void reset();

private:
    void flush();
    void arm();
    void pollLine();
    qint64 nowUs() const { return m_clock.nsecsElapsed() / 1000; }

    SimEndpoint& m_line;
    SimPacer m_pacer;
    WriteFn m_write;
    QElapsedTimer m_clock;
    QTimer m_timer;
    QTimer m_lineTimer;  // the line's own timers (3964R)
    PacedQueue m_pending;
};

}  // namespace cambench::comm
