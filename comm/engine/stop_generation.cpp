#include "stop_generation.h"

#include <QCoreApplication>

namespace cambench::comm {

namespace {
// STOPs are pressed by hand: a job spans only the last few.
constexpr std::size_t kRememberedStops = 16;
}  // namespace

quint64 StopGeneration::raise(const QString& cause) {
    std::lock_guard lock(m_mutex);
    const quint64 raised = m_current.load() + 1;
    m_raised.push_back({raised, QTime::currentTime(), cause});
    if (m_raised.size() > kRememberedStops) m_raised.pop_front();
    // Raised last: whoever sees the new generation finds its time.
    m_current.store(raised);
    return raised;
}

StopGeneration::Raised StopGeneration::firstAfter(quint64 generation) const {
    std::lock_guard lock(m_mutex);
    for (const Raised& raised : m_raised)
        if (raised.generation > generation) return raised;
    return m_raised.empty() ? Raised{generation, QTime::currentTime(), {}} : m_raised.back();
}

Error stoppedBeforeMoving(const StopGeneration::Raised& stop) {
    const QString what =
        stop.cause.isEmpty() ? QCoreApplication::translate("cambench::comm", "STOP") : stop.cause;
    return {ErrorKind::Cancelled,
            QCoreApplication::translate("cambench::comm", "stopped before it moved: %1 at %2")
                .arg(what, stop.at.toString(QStringLiteral("HH:mm:ss"))),
            0};
}

std::optional<Error> refusedByStop(const StopGeneration* stops, JobStopMark* mark,
                                   const Request& request) {
    if (!mark) return std::nullopt;
    if (mark->stopped) return mark->stopped;
    if (!stops || !request.motion || mark->askedIn >= stops->current()) return std::nullopt;
    mark->stopped = stoppedBeforeMoving(stops->firstAfter(mark->askedIn));
    return mark->stopped;
}

}  // namespace cambench::comm
