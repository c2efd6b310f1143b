#include "request_engine.h"

#include <QCoreApplication>

#include "engine_logging.h"

#include <algorithm>

namespace cambench::comm {

namespace {

// The longest a cancel request waits for the transport.
constexpr int kSliceMs = 20;
// A link layer that never finishes sending (a 3964R peer that keeps
// answering NAK has its own limit; this only bounds a broken backend).
constexpr int kSendLimitMs = 60000;
// How often one request may be resent because the device answered an older
// one instead (a Multiuser block number it had seen last).
constexpr int kMaxResends = 2;

}  // namespace

RequestEngine::RequestEngine(Transport& transport, FramingBackend& backend, EngineSettings settings)
    : m_transport(transport), m_backend(backend), m_settings(settings) {
    m_clock.start();
}

int RequestEngine::attemptTimeoutMs(const Request& request) const {
    if (request.fixedTimeoutMs > 0) return request.fixedTimeoutMs;
    const LineTiming& line = m_settings.line;
    const int derived =
        line.attemptMs(m_backend.requestWireBytes(request), m_backend.replyWireBytes(request));
    if (request.timeout == TimeoutClass::Long) {
        // A device that deduplicates is asked again every probeAfterMs; one
        // that does not is probed when a probe is known, else waited for.
        if (m_backend.deduplicatesRetries() || request.probe) return line.probeAfterMs + derived;
        return line.longWorkMs;
    }
    if (m_settings.fixedTimeoutMs > 0) return m_settings.fixedTimeoutMs;
    return derived;
}

int RequestEngine::attemptsFor(const Request& request) const {
    if (request.maxAttempts > 0) return request.maxAttempts;
    const int normal = 1 + std::max(0, m_settings.retries);
    const bool dedup = m_backend.deduplicatesRetries();
    if (request.timeout == TimeoutClass::Long && dedup) {
        // Repeats of a long request are answered, not executed: keep asking
        // until the longest working time has passed.
        const int each = std::max(1, attemptTimeoutMs(request));
        return std::max(normal, (m_settings.line.longWorkMs + each - 1) / each);
    }
    if (request.retry == RetryPolicy::Never && !dedup) return 1;
    return normal;
}

Result<QByteArray> RequestEngine::send(const Request& request) {
    ++m_stats.requests;
    m_lastAttempts = 0;
    m_lastHeardDevice = false;
    if (cancelled()) return Error::cancelled();
    dropStaleInput();
    m_backend.beginRequest(request);

    const int attempts = attemptsFor(request);
    int resends = 0;
    QString problem;
    for (int attempt = 1; attempt <= attempts; ++attempt) {
        if (cancelled()) return Error::cancelled();
        m_lastAttempts = attempt;
        if (attempt > 1) {
            ++m_stats.retries;
            qCDebug(commLinkLog) << "retrying" << request.label << "attempt" << attempt << "after"
                                 << problem;
            report(m_backend.resetInput(), false);
            m_transport.discardInput();
        }
        Result<Attempt> result = runAttempt(request, attempt);
        if (!result) return result.error();
        switch (result->outcome) {
            case Outcome::Answer:
                return result->answer;
            case Outcome::Failed:
                problem = result->problem;
                break;
            case Outcome::Resend:
                problem = result->problem;
                if (resends++ < kMaxResends) {
                    // Not executed: the same request under a new sequence number.
                    qCDebug(commLinkLog)
                        << "resending" << request.label << "as a new request:" << problem;
                    report(m_backend.resetInput(), false);
                    m_backend.beginRequest(request);
                    --attempt;
                }
                break;
        }
    }
    const QString message = failureMessage(request, attempts, attemptTimeoutMs(request), problem);
    qCWarning(commLinkLog) << message;
    return Error::communication(message);
}

Result<RequestEngine::Attempt> RequestEngine::runAttempt(const Request& request, int attempt) {
    m_sent = false;
    Attempt result;
    bool decided = false;
    const Status applied =
        apply(m_backend.startAttempt(request, attempt, now()), request, result, decided);
    if (!applied) return applied.error();
    if (decided) return result;
    return awaitAnswer(request, attemptTimeoutMs(request));
}

Result<RequestEngine::Attempt> RequestEngine::awaitAnswer(const Request& request, int timeoutMs) {
    Attempt result;
    bool decided = false;
    const qint64 sendLimit = now() + kSendLimitMs;
    qint64 deadline = -1;  // set once the request has left
    qint64 longLimit = now() + m_settings.line.longWorkMs;
    for (;;) {
        if (cancelled()) return Error::cancelled();
        if (m_sent && deadline < 0) {
            if (!request.expectReply) {
                result.outcome = Outcome::Answer;
                return result;
            }
            deadline = now() + timeoutMs;
        }
        qint64 until = m_sent ? deadline : sendLimit;
        const qint64 timer = m_backend.nextTimerMs();
        if (timer >= 0) until = std::min(until, timer);
        const int wait = int(std::clamp<qint64>(until - now(), 0, kSliceMs));
        Result<QByteArray> chunk = m_transport.read(wait);
        if (!chunk) {
            report(m_backend.resetInput(), false);
            return chunk.error();
        }
        if (!chunk->isEmpty()) {
            m_lastHeardDevice = true;
            m_stats.bytesReceived += chunk->size();
            const Status applied = apply(m_backend.feed(*chunk, now()), request, result, decided);
            if (!applied) return applied.error();
            if (decided) return result;
        }
        if (m_backend.nextTimerMs() >= 0 && now() >= m_backend.nextTimerMs()) {
            const Status applied = apply(m_backend.poll(now()), request, result, decided);
            if (!applied) return applied.error();
            if (decided) return result;
        }
        if (!m_sent && now() >= sendLimit) {
            result.problem =
                QCoreApplication::translate("cambench::comm", "the request could not be sent");
            return result;
        }
        // The request may have left during this pass (a link backend's
        // handshake): its reply deadline starts on the next pass.
        if (!m_sent || deadline < 0 || now() < deadline) continue;

        // The attempt's time is up.
        const bool probing = request.timeout == TimeoutClass::Long && request.probe &&
                             !m_backend.deduplicatesRetries() && request.fixedTimeoutMs <= 0;
        if (probing && now() < longLimit) {
            Result<Probe> probed = probe(request);
            if (!probed) return probed.error();
            if (probed->kind == Probe::StillBusy) {
                deadline = now() + m_settings.line.probeAfterMs;
                continue;
            }
            if (probed->kind == Probe::LateAnswer) {
                result.outcome = Outcome::Answer;
                result.answer = probed->answer;
                return result;
            }
            result.problem = QCoreApplication::translate("cambench::comm",
                                                         "no reply, though the device answered %1")
                                 .arg(request.probe().label);
            return result;
        }
        if (result.problem.isEmpty()) result.problem = QStringLiteral("no reply");
        return result;
    }
}

Result<RequestEngine::Probe> RequestEngine::probe(const Request& request) {
    const Request probe = request.probe();
    ++m_stats.probes;
    qCDebug(commLinkLog) << request.label << "silent; asking" << probe.label;
    report(m_backend.resetInput(), false);
    m_backend.beginRequest(probe);
    Attempt ignored;
    bool decided = false;
    m_sent = false;
    const Status applied = apply(m_backend.startAttempt(probe, 1, now()), probe, ignored, decided);
    if (!applied) return applied.error();
    // Either answer ends the wait: the long request's own (late) answer is
    // as good as ever, and the probe's means the device is not busy.
    bool late = false;
    Request both = probe;
    both.judge = [&](const QByteArray& reply, QString& problem) {
        if (request.judge && request.judge(reply, problem) == Verdict::Accept) {
            late = true;
            return Verdict::Accept;
        }
        return probe.judge ? probe.judge(reply, problem) : Verdict::Accept;
    };
    Result<Attempt> answer = awaitAnswer(both, attemptTimeoutMs(probe));
    if (!answer) return answer.error();
    if (answer->outcome != Outcome::Answer) return Probe{Probe::StillBusy, {}};
    if (late) return Probe{Probe::LateAnswer, answer->answer};
    return Probe{Probe::AnswerLost, {}};
}

Status RequestEngine::apply(BackendStep&& step, const Request& request, Attempt& attempt,
                            bool& decided) {
    if (!step.write.isEmpty()) {
        report(step.write, true);
        const Status written = m_transport.write(step.write);
        if (!written) return written;
        m_stats.bytesSent += step.write.size();
    }
    if (step.sent) m_sent = true;
    for (Incoming& in : step.incoming) {
        if (decided) {
            report(in.wire, false);
            continue;
        }
        report(in.wire, false);
        switch (in.kind) {
            case Incoming::Garbage:
                qCDebug(commLinkLog) << "skipped bytes outside a frame:" << in.wire.toHex(' ');
                break;
            case Incoming::Foreign:
                qCDebug(commLinkLog)
                    << "ignoring a frame for another device or block" << in.wire.toHex(' ');
                break;
            case Incoming::Damaged:
                ++m_stats.badFrames;
                attempt.problem = in.detail;
                attempt.outcome = Outcome::Failed;
                decided = true;
                break;
            case Incoming::Message: {
                QString problem;
                const Verdict verdict =
                    request.judge ? request.judge(in.message, problem) : Verdict::Accept;
                switch (verdict) {
                    case Verdict::Accept:
                        attempt.outcome = Outcome::Answer;
                        attempt.answer = std::move(in.message);
                        decided = true;
                        break;
                    case Verdict::Ignore:
                        break;
                    case Verdict::Retry:
                        ++m_stats.badFrames;
                        attempt.problem = problem;
                        attempt.outcome = Outcome::Failed;
                        decided = true;
                        break;
                    case Verdict::Resend:
                        attempt.problem = problem;
                        attempt.outcome = Outcome::Resend;
                        decided = true;
                        break;
                }
                break;
            }
        }
    }
    if (!decided && !step.linkFailure.isEmpty()) {
        attempt.problem = step.linkFailure;
        attempt.outcome = Outcome::Failed;
        decided = true;
    }
    return success();
}

QString RequestEngine::failureMessage(const Request& request, int attempts, int timeoutMs,
                                      const QString& problem) const {
    const QString what =
        problem == QLatin1String("no reply")
            ? QCoreApplication::translate("cambench::comm", "no reply")
            : QCoreApplication::translate("cambench::comm", "no valid reply (last: %1)")
                  .arg(problem);
    // Whole phrases, so that a translation can put its own plural.
    const QString tries =
        attempts == 1 ? QCoreApplication::translate("cambench::comm", "1 attempt")
                      : QCoreApplication::translate("cambench::comm", "%1 attempts").arg(attempts);
    return QCoreApplication::translate("cambench::comm",
                                       "%1 from %2 to %3 on %4 after %5 of %6 ms; %7")
        .arg(what, m_backend.describe(), request.label, m_transport.description(), tries)
        .arg(timeoutMs)
        .arg(m_backend.checkHint());
}

void RequestEngine::report(const QByteArray& bytes, bool outgoing) {
    if (!m_sink || bytes.isEmpty()) return;
    m_sink(TrafficEntry{QDateTime::currentDateTime(), outgoing,
                        m_backend.maskForLog(bytes, outgoing)});
}

void RequestEngine::dropStaleInput() {
    report(m_backend.resetInput(), false);
    // A late answer to an earlier request must not pass for the next one's.
    const Result<QByteArray> stale = m_transport.read(0);
    if (stale && !stale->isEmpty()) {
        m_stats.bytesReceived += stale->size();
        qCDebug(commLinkLog) << "dropping" << stale->size() << "stale bytes";
        report(*stale, false);
    }
}

}  // namespace cambench::comm
