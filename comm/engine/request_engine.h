#pragma once

#include "framing_backend.h"
#include "line_timing.h"
#include "request.h"
#include "traffic_entry.h"

#include "comm/transport/transport.h"
#include "model/result.h"

#include <QElapsedTimer>

#include <atomic>
#include <functional>

namespace cambench::comm {

struct EngineSettings {
    LineTiming line;
    int retries = 3;          // further attempts after the first, where a retry is safe
    int fixedTimeoutMs = 0;   // > 0: every normal attempt waits this long (the user's --timeout)
};

// Sends requests over a Transport through one FramingBackend and waits for
// their answers: the protocol-neutral half of every protocol. Owns the
// per-attempt timeout (derived from the line unless fixed), the retries
// (only where RetryPolicy and the backend make them safe), cancel, the
// traffic sink and the counters. Lives in the worker thread; every call
// blocks that thread only.
class RequestEngine {
public:
    RequestEngine(Transport& transport, FramingBackend& backend, EngineSettings settings = {});

    const EngineSettings& settings() const { return m_settings; }
    void setSettings(const EngineSettings& settings) { m_settings = settings; }
    FramingBackend& backend() { return m_backend; }
    Transport& transport() { return m_transport; }

    // Set from any thread; an ongoing call returns Cancelled within ~20 ms.
    void setCancelFlag(const std::atomic_bool* flag) { m_cancel = flag; }
    void setTrafficSink(std::function<void(const TrafficEntry&)> sink) { m_sink = std::move(sink); }

    // Sends `request` and returns the accepted reply message. Fails with a
    // Communication error naming the request, the line and what to check.
    Result<QByteArray> send(const Request& request);

    // The per-attempt timeout `request` gets.
    int attemptTimeoutMs(const Request& request) const;

    // How many times the last call sent its request. Above 1 an earlier
    // attempt may have reached the device and been executed although its
    // reply was lost (see RetryPolicy::CheckAfter).
    int lastAttempts() const { return m_lastAttempts; }
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
    };

    int attemptsFor(const Request& request) const;
    Result<Attempt> runAttempt(const Request& request, int attempt);
    Result<Attempt> awaitAnswer(const Request& request, int timeoutMs);
    // Handles one backend step: writes, logs, judges. Sets `decided` when
    // the attempt is over.
    Status apply(BackendStep&& step, const Request& request, Attempt& attempt, bool& decided);
    // What asking a silent device with the request's probe showed.
    struct Probe {
        enum Kind { StillBusy, AnswerLost, LateAnswer } kind = StillBusy;
        QByteArray answer;  // LateAnswer: the long request's own answer
    };
    Result<Probe> probe(const Request& request);
    QString failureMessage(const Request& request, int attempts, int timeoutMs,
                           const QString& problem) const;
    bool cancelled() const { return m_cancel && m_cancel->load(); }
    qint64 now() const { return m_clock.elapsed(); }
    void report(const QByteArray& bytes, bool outgoing);
    void dropStaleInput();

    Transport& m_transport;
    FramingBackend& m_backend;
    EngineSettings m_settings;
    const std::atomic_bool* m_cancel = nullptr;
    std::function<void(const TrafficEntry&)> m_sink;
    QElapsedTimer m_clock;
    Stats m_stats;
    int m_lastAttempts = 0;
    bool m_lastHeardDevice = false;
    bool m_sent = false;
};

}  // namespace cambench::comm
