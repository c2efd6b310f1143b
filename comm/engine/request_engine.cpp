#include "request_engine.h"

#include "between_requests.h"

#include <QCoreApplication>

#include "engine_logging.h"

#include <algorithm>
#include <utility>

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

bool couldBeAnswer(const Incoming& in) {
    return in.kind == Incoming::Message || in.kind == Incoming::Damaged;
}

}  // namespace

RequestEngine::RequestEngine(Transport& transport, FramingBackend& backend, EngineSettings settings)
    : m_transport(transport), m_backend(backend), m_settings(settings) {
    m_clock.start();
    m_backend.setLineTiming(m_settings.line);
}

void RequestEngine::setSettings(const EngineSettings& settings) {
    m_settings = settings;
    m_backend.setLineTiming(m_settings.line);
}

RequestEngine::Window RequestEngine::windowFor(const Request& request) const {
    if (request.fixedTimeoutMs > 0) return {request.fixedTimeoutMs, request.fixedTimeoutMs};
    LineTiming line = m_settings.line;
    if (request.turnaroundMs >= 0) line.turnaroundMs = request.turnaroundMs;
    const qint64 requestBytes = m_backend.requestWireBytes(request);
    const int latency = m_backend.replyLatencyMs();
    const int full = line.attemptMs(requestBytes, m_backend.replyWireBytes(request)) + latency;
    if (request.timeout == TimeoutClass::Long) {
        // A device that deduplicates is asked again every probeAfterMs; one
        // that does not is probed when a probe is known, else waited for.
        const int longMs = (m_backend.deduplicatesRetries() || request.probe)
                               ? line.probeAfterMs + full
                               : line.longWorkMs;
        return {longMs, longMs};
    }
    if (m_settings.fixedTimeoutMs > 0 && request.turnaroundMs < 0)
        return {m_settings.fixedTimeoutMs, m_settings.fixedTimeoutMs};
    return {std::min(full, line.firstByteMs(requestBytes) + latency), full};
}

int RequestEngine::attemptTimeoutMs(const Request& request) const {
    return windowFor(request).fullMs;
}

int RequestEngine::firstByteTimeoutMs(const Request& request) const {
    return windowFor(request).firstByteMs;
}

int RequestEngine::lateAnswerWindowMs(const Request& request) const {
    // A long request waits (and probes) for its answer anyway; a short look
    // at a bus address must stay short.
    if (request.timeout != TimeoutClass::Normal || request.silenceExpected || !request.expectReply)
        return 0;
    return std::max(0, m_backend.lateAnswerWindowMs());
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
    {
        // An urgent job (a STOP) runs here between two requests of the
        // running job; a read-only check's gate is not for it.
        RequestGate held = std::exchange(m_gate, {});
        BetweenRequests::run();
        m_gate = std::move(held);
    }
    // A late answer the line may still carry is waited out first, so that
    // a STOP during that wait is seen by the check below.
    if (m_unsettled && !request.silenceExpected) {
        if (cancelled()) return Error::cancelled();
        if (const Status settled = settleLine(); !settled) return settled.error();
    }
    // After a STOP nothing of a job asked before it moves.
    if (std::optional<Error> stopped = refusedByStop(m_stops, m_jobStop, request)) {
        ++m_stats.refusedByStop;
        return *std::move(stopped);
    }
    if (m_gate) {
        if (const QString refused = m_gate(request); !refused.isEmpty()) {
            ++m_stats.refusedByGate;
            return Error::usage(refused);
        }
    }
    ++m_stats.requests;
    m_lastAttempts = 0;
    m_lastHeardDevice = false;
    if (cancelled()) return Error::cancelled();
    dropStaleInput();
    m_backend.beginRequest(request);

    const int attempts = attemptsFor(request);
    const int lateWindow = lateAnswerWindowMs(request);
    int resends = 0;
    int silentAttempts = 0;
    int unheardAttempts = 0;  // silent, and nothing came in their late-answer window either
    qint64 firstStart = -1;
    QString problem;
    for (int attempt = 1; attempt <= attempts; ++attempt) {
        if (cancelled()) return Error::cancelled();
        // A STOP while an earlier attempt waited: no motion is sent again
        // (the check above ran before that wait).
        if (attempt > 1) {
            if (std::optional<Error> stopped = refusedByStop(m_stops, m_jobStop, request)) {
                ++m_stats.refusedByStop;
                return *std::move(stopped);
            }
        }
        m_lastAttempts = attempt;
        if (attempt > 1) {
            ++m_stats.retries;
            qCDebug(commLinkLog) << "retrying" << request.label << "attempt" << attempt << "after"
                                 << problem;
            report(m_backend.resetInput(), false);
            m_transport.discardInput();
        }
        const qint64 start = now();
        if (firstStart < 0) firstStart = start;
        Result<Attempt> result = runAttempt(request, attempt);
        if (result && result->outcome == Outcome::Failed && result->silent) {
            ++silentAttempts;
            ++m_stats.silentAttempts;
            if (lateWindow > 0) {
                // The answer may only be late: nothing else goes out until the
                // line has been quiet for the window, and what comes meanwhile
                // is this request's (the line was quiet before it was sent).
                ++m_stats.lateAnswerWaits;
                const int whole = m_settings.line.wireMs(m_backend.replyWireBytes(request));
                result = awaitAnswer(request, Window{lateWindow, lateWindow + whole});
                if (result && result->outcome == Outcome::Answer) ++m_stats.lateAnswersTaken;
                if (result && result->outcome == Outcome::Failed && result->silent)
                    ++unheardAttempts;
            } else if (request.silenceExpected) {
                // A short look (a bus scan): its answer may come yet. The
                // next request that is not such a look waits for a quiet line.
                if (m_backend.lateAnswerWindowMs() > 0) m_unsettled = true;
            }
        }
        if (!result) {
            // Cancelled while an answer may be on its way.
            if (m_backend.lateAnswerWindowMs() > 0) m_unsettled = true;
            return result.error();
        }
        switch (result->outcome) {
            case Outcome::Answer:
                if (unheardAttempts > 0) {
                    // An earlier attempt stayed silent past its window, so this
                    // answer may be that one's, and this attempt's may come yet.
                    m_unsettled = true;
                }
                if (lateWindow == 0 && silentAttempts > 0 && !m_backend.deduplicatesRetries() &&
                    request.timeout == TimeoutClass::Normal) {
                    // Without sequence numbers a silent attempt may have been a
                    // slow one: its answer may be the one just accepted, and the
                    // answer to this attempt may still come, as late after this
                    // attempt as that one was. Drop what arrives until then (and
                    // for the time such an answer takes on the wire), so that
                    // the next request of the same command cannot take it.
                    const qint64 slowest = start - firstStart;
                    const int whole = m_settings.line.wireMs(m_backend.replyWireBytes(request));
                    const Status drained = drain(now() + slowest + whole, silentAttempts);
                    if (!drained) return drained.error();
                }
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
    const QString message = failureMessage(request, attempts, problem);
    if (request.silenceExpected) {
        qCDebug(commLinkLog) << message;
    } else {
        qCWarning(commLinkLog) << message;
    }
    return Error::communication(message);
}

Status RequestEngine::listen(int ms) {
    dropStaleInput();
    const Status drained = drain(now() + std::max(0, ms), 0);
    report(m_backend.resetInput(), false);
    return drained;
}

Result<RequestEngine::Attempt> RequestEngine::runAttempt(const Request& request, int attempt) {
    m_sent = false;
    Attempt result;
    bool decided = false;
    const Status applied =
        apply(m_backend.startAttempt(request, attempt, now()), request, result, decided);
    if (!applied) return applied.error();
    if (decided) return result;
    return awaitAnswer(request, windowFor(request));
}

Result<RequestEngine::Attempt> RequestEngine::awaitAnswer(const Request& request,
                                                          const Window& window) {
    Attempt result;
    bool decided = false;
    const qint64 sendLimit = now() + kSendLimitMs;
    qint64 sentAt = -1;
    qint64 deadline = -1;  // set once the request has left
    const qint64 longLimit = now() + m_settings.line.longWorkMs;
    for (;;) {
        if (cancelled()) return Error::cancelled();
        if (m_sent && sentAt < 0) {
            if (!request.expectReply) {
                result.outcome = Outcome::Answer;
                return result;
            }
            sentAt = now();
            deadline = sentAt + window.firstByteMs;
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
            m_stats.bytesReceived += chunk->size();
            BackendStep step = m_backend.feed(*chunk, now());
            if (!m_backend.carriesOtherTraffic() || step.sent ||
                std::any_of(step.incoming.cbegin(), step.incoming.cend(), couldBeAnswer)) {
                m_lastHeardDevice = true;
                if (sentAt >= 0) {
                    // A reply is arriving: it gets the time its longest form needs.
                    result.silent = false;
                    deadline = std::max(deadline, sentAt + window.fullMs);
                }
            }
            const Status applied = apply(std::move(step), request, result, decided);
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
            result.silent = false;  // the device is there: it answered the probe
            result.problem = QCoreApplication::translate("cambench::comm",
                                                         "no reply, though the device answered %1")
                                 .arg(request.probe().label);
            return result;
        }
        if (result.problem.isEmpty())
            result.problem = QCoreApplication::translate("cambench::comm", "no reply");
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
    Result<Attempt> answer = awaitAnswer(both, windowFor(probe));
    if (!answer) return answer.error();
    if (answer->outcome != Outcome::Answer) return Probe{Probe::StillBusy, {}};
    if (late) return Probe{Probe::LateAnswer, answer->answer};
    return Probe{Probe::AnswerLost, {}};
}

Status RequestEngine::apply(BackendStep&& step, const Request& request, Attempt& attempt,
                            bool& decided) {
    if (!step.write.isEmpty()) {
        if (!step.quiet) report(step.write, true);
        const Status written = m_transport.write(step.write);
        if (!written) return written;
        m_stats.bytesSent += step.write.size();
    }
    if (step.sent) m_sent = true;
    for (Incoming& in : step.incoming) {
        report(in.wire, false);
        if (m_observer) m_observer(in);
        if (decided) continue;
        switch (in.kind) {
            case Incoming::Garbage:
                qCDebug(commLinkLog) << "skipped bytes outside a frame:" << in.detail;
                break;
            case Incoming::Foreign:
                qCDebug(commLinkLog) << "ignoring a frame for another device or block";
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

Result<int> RequestEngine::consume(BackendStep&& step) {
    if (!step.write.isEmpty()) {
        if (!step.quiet) report(step.write, true);
        const Status written = m_transport.write(step.write);
        if (!written) return written.error();
        m_stats.bytesSent += step.write.size();
    }
    int answers = 0;
    for (const Incoming& in : step.incoming) {
        report(in.wire, false);
        if (m_observer) m_observer(in);
        if (couldBeAnswer(in)) ++answers;
    }
    return answers;
}

Status RequestEngine::settleLine() {
    ++m_stats.settles;
    qCDebug(commLinkLog) << "an earlier answer may still come: waiting for a quiet line";
    const int window = m_backend.lateAnswerWindowMs();
    const Status drained = drain(now() + window, 0, window);
    if (!drained) return drained;
    if (cancelled()) return Error::cancelled();
    m_unsettled = false;
    return success();
}

Status RequestEngine::drain(qint64 untilMs, int enough, int quietMs) {
    int answers = 0;
    while (now() < untilMs && (enough <= 0 || answers < enough) && !cancelled()) {
        qint64 until = untilMs;
        const qint64 timer = m_backend.nextTimerMs();
        if (timer >= 0) until = std::min(until, timer);
        const Result<QByteArray> chunk =
            m_transport.read(int(std::clamp<qint64>(until - now(), 0, kSliceMs)));
        if (!chunk) return chunk.error();
        BackendStep step;
        if (!chunk->isEmpty()) {
            m_stats.bytesReceived += chunk->size();
            step = m_backend.feed(*chunk, now());
        }
        if (m_backend.nextTimerMs() >= 0 && now() >= m_backend.nextTimerMs())
            step.append(m_backend.poll(now()));
        if (quietMs > 0 && !chunk->isEmpty()) untilMs = std::max(untilMs, now() + quietMs);
        const Result<int> seen = consume(std::move(step));
        if (!seen) return seen.error();
        if (*seen > 0 && (enough > 0 || quietMs > 0)) {
            m_stats.lateReplies += *seen;
            qCDebug(commLinkLog) << "dropped" << *seen << "late answer(s) to an earlier attempt";
        }
        answers += *seen;
    }
    return success();
}

QString RequestEngine::failureMessage(const Request& request, int attempts,
                                      const QString& problem) const {
    const QString noReply = QCoreApplication::translate("cambench::comm", "no reply");
    const bool silent = problem == noReply;
    const QString what =
        silent ? noReply
               : QCoreApplication::translate("cambench::comm", "no valid reply (last: %1)")
                     .arg(problem);
    const int waitedMs = silent ? firstByteTimeoutMs(request) + lateAnswerWindowMs(request)
                                : attemptTimeoutMs(request);
    // Whole phrases, so that a translation can put its own plural.
    const QString tries =
        attempts == 1 ? QCoreApplication::translate("cambench::comm", "1 attempt")
                      : QCoreApplication::translate("cambench::comm", "%1 attempts").arg(attempts);
    return QCoreApplication::translate("cambench::comm",
                                       "%1 from %2 to %3 on %4 after %5 of %6 ms; %7")
        .arg(what, m_backend.describe(), request.label, m_transport.description(), tries)
        .arg(waitedMs)
        .arg(m_backend.checkHint());
}

void RequestEngine::report(const QByteArray& bytes, bool outgoing) {
    if (!m_sink || bytes.isEmpty()) return;
    m_sink(TrafficEntry{QDateTime::currentDateTime(), outgoing,
                        m_backend.maskForLog(bytes, outgoing)});
}

void RequestEngine::dropStaleInput() {
    report(m_backend.resetInput(), false);
    // A late answer to an earlier request must not pass for the next one's;
    // the observer still hears it (a bus scan learns who answered late).
    const Result<QByteArray> stale = m_transport.read(0);
    if (stale && !stale->isEmpty()) {
        m_stats.bytesReceived += stale->size();
        qCDebug(commLinkLog) << "dropping" << stale->size() << "stale bytes";
        const Result<int> seen = consume(m_backend.feed(*stale, now()));
        Q_UNUSED(seen);
        report(m_backend.resetInput(), false);
    }
}

}  // namespace cambench::comm
