#pragma once

#include "request.h"

#include "model/result.h"

#include <QTime>

#include <atomic>
#include <deque>
#include <mutex>
#include <optional>

namespace cambench::comm {

// The STOP generation of one device connection (issue 35): after a STOP
// nothing moves until the person asks again. Every STOP raises it at once,
// on the thread that asks for the STOP (not when the STOP's job runs);
// every job records the generation current when it was asked. The engine
// refuses a request that can start or continue motion or change a drive's
// power (Request::motion) of a job asked in an older generation, before
// it leaves. Thread-safe: raised by the GUI or a signal's watcher, read by
// the worker.
class StopGeneration {
public:
    quint64 current() const { return m_current.load(); }
    // A STOP was asked: no motion of a job asked before it from now on.
    // `cause` names it where it is not the STOP ("SIGINT"). Returns the new
    // generation.
    quint64 raise(const QString& cause = {});

    // The first STOP after a generation: the one that overtook a job asked
    // in it (the oldest remembered, if that one is forgotten).
    struct Raised {
        quint64 generation = 0;
        QTime at;
        QString cause;  // empty: the STOP
    };
    Raised firstAfter(quint64 generation) const;

private:
    std::atomic<quint64> m_current{0};
    mutable std::mutex m_mutex;
    std::deque<Raised> m_raised;  // the last few
};

// A running job as the engine sees it: the STOP generation it was asked in
// and, once the engine refused one of its motion requests, why. From then
// on nothing more is sent for it, queries neither.
struct JobStopMark {
    quint64 askedIn = 0;
    std::optional<Error> stopped;
};

// Cancelled: "stopped before it moved: STOP at 14:02:11".
Error stoppedBeforeMoving(const StopGeneration::Raised& stop);

// What the engine says of `request` of the job `mark` (none: not in a job;
// `stops` none: no STOP on this line): nothing when it may leave, else the
// job's refusal, which from now on is the job's answer to everything.
std::optional<Error> refusedByStop(const StopGeneration* stops, JobStopMark* mark,
                                   const Request& request);

}  // namespace cambench::comm
