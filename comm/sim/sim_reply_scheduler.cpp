#include "sim_reply_scheduler.h"

#include <algorithm>
#include <utility>

namespace cambench::comm {

SimReplyScheduler::SimReplyScheduler(SimLine& line, const SimPacer& pacer, WriteFn write,
                                     QObject* parent)
    : QObject(parent), m_line(line), m_pacer(pacer), m_write(std::move(write)) {
    m_clock.start();
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &SimReplyScheduler::flush);
}

void SimReplyScheduler::received(const QByteArray& bytes) {
    m_pending.append(m_pacer.schedule(nowUs(), int(bytes.size()), m_line.feed(bytes)));
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
    const auto due = m_pending.nextDueUs();
    if (!due) return;
    const qint64 waitUs = *due - nowUs();
    // Round up: waking early would only find nothing due and re-arm.
    m_timer.start(int(std::clamp<qint64>((waitUs + 999) / 1000, 0, 60000)));
}

}  // namespace cambench::comm
