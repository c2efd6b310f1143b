#include "sim_reply_scheduler.h"

#include <algorithm>
#include <utility>

namespace cambench::comm {

SimReplyScheduler::SimReplyScheduler(SimEndpoint& line, const SimPacer& pacer, WriteFn write,
                                     QObject* parent)
    : QObject(parent), m_line(line), m_pacer(pacer), m_write(std::move(write)) {
    m_clock.start();
    for (QTimer* timer : {&m_timer, &m_lineTimer}) {
        timer->setSingleShot(true);
        timer->setTimerType(Qt::PreciseTimer);
    }
    connect(&m_timer, &QTimer::timeout, this, &SimReplyScheduler::flush);
    connect(&m_lineTimer, &QTimer::timeout, this, &SimReplyScheduler::pollLine);
    // A line with a life of its own (a token bus) runs before the PC speaks.
    arm();
}

void SimReplyScheduler::received(const QByteArray& bytes) {
    const qint64 now = nowUs();
    m_pending.append(m_pacer.schedule(now, int(bytes.size()), m_line.receive(bytes, now / 1000)));
    flush();
}

void SimReplyScheduler::pollLine() {
    const qint64 now = nowUs();
    m_pending.append(m_pacer.schedule(now, 0, m_line.poll(now / 1000)));
    flush();
}

void SimReplyScheduler::reset() {
    m_pending.clear();
    m_pacer.reset();
    m_timer.stop();
}

void SimReplyScheduler::flush() {
    const QByteArray out = m_pending.takeDue(nowUs());
    if (!out.isEmpty()) m_write(out);
    arm();
}

void SimReplyScheduler::arm() {
    if (const qint64 timer = m_line.nextTimerMs(); timer >= 0) {
        // Round up, so that the line's deadline has passed when it runs.
        m_lineTimer.start(int(std::clamp<qint64>(timer - nowUs() / 1000 + 1, 0, 60000)));
    } else {
        m_lineTimer.stop();
    }
    const auto due = m_pending.nextDueUs();
    if (!due) return;
    const qint64 waitUs = *due - nowUs();
    // Round up: waking early would only find nothing due and re-arm.
    m_timer.start(int(std::clamp<qint64>((waitUs + 999) / 1000, 0, 60000)));
}

}  // namespace cambench::comm
