#pragma once

#include "comm/traffic/traffic_entry.h"
#include "framing_backend.h"
#include "line_timing.h"
#include "request.h"
#include "stop_generation.h"

#include "comm/transport/transport.h"
#include "model/result.h"

#include <QElapsedTimer>

#include <atomic>
#include <functional>

namespace cambench::comm {

struct EngineSettings {
    LineTiming line;
    int retries = 3;         // further attempts after the first, where a retry is safe
    int fixedTimeoutMs = 0;  // > 0: every normal attempt waits this long (the user's --timeout)
};

// Sends requests over a Transport through one FramingBackend and waits for
// their answers: the protocol-neutral half of every protocol. Owns the
// per-attempt timeout (derived from the line unless fixed), the retries
// (only where RetryPolicy and the backend make them safe), cancel, the
// traffic sink and the counters. Lives in the worker thread; every call
// blocks that thread only.
//
// An attempt ends early when it can: a silent line past the first reply
// byte's time is a lost reply, a damaged frame fails at once, and a frame
// that broke off is caught by the backend's gap timer. Only a reply that is
// arriving gets the whole attempt time.
class RequestEngine {
public:
    RequestEngine(Transport& transport, FramingBackend& backend, EngineSettings settings = {});

    const EngineSettings& settings() const { return m_settings; }
    void setSettings(const EngineSettings& settings);
    FramingBackend& backend() { return m_backend; }
    Transport& transport() { return m_transport; }

    // Set from any thread; an ongoing call returns Cancelled within ~20 ms.
    void setCancelFlag(const std::atomic_bool* flag) { m_cancel = flag; }
    void setTrafficSink(std::function<void(const TrafficEntry&)> sink) { m_sink = std::move(sink); }
    // Sees every piece of input the backend makes of the line, judged or
    // not, stale or late (a bus scan hears late answers by their source).
    using IncomingObserver = std::function<void(const Incoming&)>;
    void setIncomingObserver(IncomingObserver observer) { m_observer = std::move(observer); }
    // Sees every request before it is sent: a request it refuses (its
    // reason, non-empty) fails with Usage and never reaches the line. A
    // check that must only read installs one (ReadOnlyGate); none = all go.
    using RequestGate = std::function<QString(const Request&)>;
    void setRequestGate(RequestGate gate) { m_gate = std::move(gate); }
    // The line's STOP generation (the worker's) and the running job's mark:
    // a motion request of a job asked before the last STOP is refused, and
    // nothing more of that job is sent (stop_generation.h). None: no check.
    void setStopGeneration(const StopGeneration* stops) { m_stops = stops; }
    void setJobStopMark(JobStopMark* mark) { m_jobStop = mark; }
    // Tests: a virtual clock (ms) instead of the wall clock; the transport
    // must advance it while it "waits".
    void setClock(std::function<qint64()> nowMs) { m_clockFn = std::move(nowMs); }

    // Sends `request` and returns the accepted reply message. Fails with a
    // Communication error naming the request, the line and what to check.
    Result<QByteArray> send(const Request& request);

    // Reads the line for `ms` without sending anything: what arrives goes to
    // the observer and the traffic log only.
    Status listen(int ms);

    // The per-attempt timeout `request` gets: the whole reply at the latest.
    int attemptTimeoutMs(const Request& request) const;
    // How long an attempt waits on a silent line before it counts as lost.
    int firstByteTimeoutMs(const Request& request) const;

    // How many times the last call sent its request. Above 1 an earlier
    // attempt may have reached the device and been executed although its
    // reply was lost (see RetryPolicy::CheckAfter).
    int lastAttempts() const { return m_lastAttempts; }
    // The last call's request may have been executed more than once: it went
    // out again and the protocol does not answer repeats without executing.
    bool lastCallMayHaveActedTwice() const {
        return m_lastAttempts > 1 && !m_backend.deduplicatesRetries();
    }
    // Whether bytes came back during the last call, valid or not: with
    // stale input dropped before each request, the device then received
    // the request and answered, so a failed call may still have acted.
    bool lastCallHeardDevice() const { return m_lastHeardDevice; }

    struct Stats {
        qint64 bytesSent = 0;
        qint64 bytesReceived = 0;
        int requests = 0;
        int retries = 0;
        int badFrames = 0;
        int probes = 0;
        int silentAttempts = 0;  // attempts that heard nothing at all
        int lateReplies = 0;     // answers to an earlier attempt, dropped after a retry
        // A protocol with a late-answer window (FramingBackend::lateAnswerWindowMs):
        int lateAnswerWaits = 0;   // silent attempts followed by a wait for their answer
        int lateAnswersTaken = 0;  // answers that came in such a wait
        int settles = 0;           // waits for a quiet line before a request
        int refusedByGate = 0;     // requests the request gate kept off the line
        int refusedByStop = 0;     // requests of a job a STOP overtook, kept off the line
    };
    const Stats& stats() const { return m_stats; }
    void resetStats() { m_stats = {}; }

private:
    // The outcome of one attempt's wait.
    enum class Outcome { Answer, Failed, Resend };
    struct Attempt {
        Outcome outcome = Outcome::Failed;
        QByteArray answer;
        QString problem;
        bool silent = true;  // no byte came back after the request had left
    };
    // From the moment the request has left: until the first reply byte, and
    // until the last byte of the longest reply.
    struct Window {
        int firstByteMs = 0;
        int fullMs = 0;
    };

    Window windowFor(const Request& request) const;
    int attemptsFor(const Request& request) const;
    Result<Attempt> runAttempt(const Request& request, int attempt);
    Result<Attempt> awaitAnswer(const Request& request, const Window& window);
    // Handles one backend step: writes, logs, judges. Sets `decided` when
    // the attempt is over.
    Status apply(BackendStep&& step, const Request& request, Attempt& attempt, bool& decided);
    // Handles a step outside any attempt: writes and logs it, tells the
    // observer, judges nothing. Returns how many frames it held that could
    // have been an answer (Message, Damaged).
    Result<int> consume(BackendStep&& step);
    // Reads until `untilMs`, or until `enough` answers (Message, Damaged)
    // went by when `enough` > 0; nothing is judged. `quietMs` > 0: also
    // until the line has been quiet that long (what arrives moves the end).
    Status drain(qint64 untilMs, int enough, int quietMs = 0);
    // The late-answer window that applies to `request` (0: none).
    int lateAnswerWindowMs(const Request& request) const;
    // Before anything is sent while an answer to an earlier request may
    // still come: reads until the line has been quiet for the window.
    Status settleLine();
    // What asking a silent device with the request's probe showed.
    struct Probe {
        enum Kind { StillBusy, AnswerLost, LateAnswer } kind = StillBusy;
        QByteArray answer;  // LateAnswer: the long request's own answer
    };
    Result<Probe> probe(const Request& request);
    QString failureMessage(const Request& request, int attempts, const QString& problem) const;
    bool cancelled() const { return m_cancel && m_cancel->load(); }
    qint64 now() const { return m_clockFn ? m_clockFn() : m_clock.elapsed(); }
    void report(const QByteArray& bytes, bool outgoing);
    void dropStaleInput();

    Transport& m_transport;
    FramingBackend& m_backend;
    EngineSettings m_settings;
    const std::atomic_bool* m_cancel = nullptr;
    std::function<void(const TrafficEntry&)> m_sink;
    IncomingObserver m_observer;
    RequestGate m_gate;
    const StopGeneration* m_stops = nullptr;
    JobStopMark* m_jobStop = nullptr;
    std::function<qint64()> m_clockFn;
    QElapsedTimer m_clock;
    Stats m_stats;
    int m_lastAttempts = 0;
    bool m_lastHeardDevice = false;
    bool m_sent = false;
    // An answer to an earlier request may still come (late-answer window).
    bool m_unsettled = false;
};

}  // namespace cambench::comm
