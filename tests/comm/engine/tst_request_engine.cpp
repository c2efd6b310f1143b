// The RequestEngine with a fake framing over a scripted line on a virtual
// clock: what is sent, how often and when, without the CamCon protocol.
#include "scripted_line.h"

#include "comm/engine/request_engine.h"

#include <QtTest>

#include <atomic>

using namespace cambench;
using namespace cambench::comm;
using namespace cambench::comm::test;

namespace {

QList<ScriptedReply> silence() {
    return {};
}

QList<ScriptedReply> replyAfter(qint64 ms, const QByteArray& line) {
    return {{ms, line + '\n'}};
}

Request query(const QByteArray& message, RetryPolicy retry = RetryPolicy::Idempotent) {
    Request request;
    request.label = QString::fromLatin1(message);
    request.message = message;
    request.longestReplyBytes = 20;
    request.retry = retry;
    return request;
}

// A long request whose probe is "?probe"; the probe's answer is "probe-ok".
Request longRequest(RetryPolicy retry) {
    Request request = query("!long", retry);
    request.timeout = TimeoutClass::Long;
    request.judge = [](const QByteArray& reply, QString&) {
        return reply == "long-ok" ? Verdict::Accept : Verdict::Ignore;
    };
    request.probe = [] {
        Request probe = query("?probe");
        probe.judge = [](const QByteArray& reply, QString&) {
            return reply == "probe-ok" ? Verdict::Accept : Verdict::Ignore;
        };
        return probe;
    };
    return request;
}

// The engine, its fake backend and the scripted line of one test.
struct Rig {
    explicit Rig(ScriptedLine::Script script, bool deduplicates = false, int baud = 9600)
        : backend(deduplicates),
          line(clock, std::move(script)),
          engine(line, backend, settings(baud)) {
        engine.setClock([this] { return clock.nowMs; });
    }

    static EngineSettings settings(int baud) {
        EngineSettings settings;
        settings.line.baud = baud;
        settings.retries = 3;
        return settings;
    }

    qint64 writeGap(int index) const {
        return line.writes().at(index).atMs - line.writes().at(index - 1).atMs;
    }

    VirtualClock clock;
    FakeBackend backend;
    ScriptedLine line;
    RequestEngine engine;
};

bool startsWith(const QByteArray& written, const char* message) {
    return written.startsWith(message);
}

}  // namespace

class TestRequestEngine : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void timeoutsAreDerivedFromTheBaudRate();
    void silentAttemptEndsAtTheFirstByteTime();
    void arrivingReplyGetsTheWholeAttempt();
    void fixedTimeoutReplacesTheDerivedOne();
    void idempotentRequestIsRetriedAfterSilence();
    void neverRequestIsSentOnceWithoutDeduplication();
    void neverRequestIsRetriedWhenTheProtocolDeduplicates();
    void checkAfterRequestIsRetriedAndFlagged();
    void damagedReplyIsRetriedAtOnce();
    void foreignFrameIsIgnored();
    void resendTakesANewSequenceNumber();
    void lateAnswerToASilentAttemptIsDropped();
    void longRequestWhoseProbeIsAnsweredFailsTheAttempt();
    void longRequestKeepsWaitingWhileTheProbeIsSilent();
    void lateAnswerDuringTheProbeIsAccepted();
    void longRequestIsRepeatedWhenTheProtocolDeduplicates();
    void cancelEndsTheWait();
    void observerHearsStaleAndListenedFrames();
    void failureMessageNamesAttemptsAndTime();
    void aLateAnswerIsItsOwnRequests_data();
    void aLateAnswerIsItsOwnRequests();
    void anAnswerAfterAnUnheardAttemptSettlesTheLineFirst();
    void aLineWithoutSilenceWaitsNoLonger();
    void aShortLookStaysShortAndTheNextRequestWaitsForQuiet();
};

void TestRequestEngine::timeoutsAreDerivedFromTheBaudRate() {
    Rig slow([](const QByteArray&, int) { return silence(); }, false, 9600);
    Rig fast([](const QByteArray&, int) { return silence(); }, false, 38400);
    const Request request = query("?abcdefgh");  // 12 bytes out, up to 21 back
    const LineTiming line;
    QCOMPARE(slow.engine.attemptTimeoutMs(request),
             (33 * 10 * 1000 + 9599) / 9600 + line.turnaroundMs);
    QCOMPARE(fast.engine.attemptTimeoutMs(request),
             (33 * 10 * 1000 + 38399) / 38400 + line.turnaroundMs);
    QCOMPARE(slow.engine.firstByteTimeoutMs(request),
             (13 * 10 * 1000 + 9599) / 9600 + line.turnaroundMs);
    QVERIFY(fast.engine.firstByteTimeoutMs(request) < slow.engine.firstByteTimeoutMs(request));
    // Eleven bits per byte (a parity bit) make the same bytes slower.
    EngineSettings parity = Rig::settings(9600);
    parity.line.bitsPerByte = 11;
    slow.engine.setSettings(parity);
    QCOMPARE(slow.engine.attemptTimeoutMs(request),
             (33 * 11 * 1000 + 9599) / 9600 + line.turnaroundMs);
}

void TestRequestEngine::silentAttemptEndsAtTheFirstByteTime() {
    Rig rig([](const QByteArray&, int) { return silence(); });
    const Request request = query("?x");
    const Result<QByteArray> reply = rig.engine.send(request);
    QVERIFY(!reply.ok());
    QCOMPARE(rig.line.writes().size(), 4);
    for (int i = 1; i < 4; ++i)
        QCOMPARE(rig.writeGap(i), qint64(rig.engine.firstByteTimeoutMs(request)));
    QCOMPARE(rig.engine.stats().silentAttempts, 4);
}

void TestRequestEngine::arrivingReplyGetsTheWholeAttempt() {
    // The first byte comes just before the first-byte time, the rest of the
    // line (a slow device, a long reply) only near the end of the attempt.
    Rig rig([](const QByteArray&, int) { return silence(); });
    const Request request = query("?x");
    const int firstByte = rig.engine.firstByteTimeoutMs(request);
    const int whole = rig.engine.attemptTimeoutMs(request);
    QVERIFY(firstByte < whole);
    rig.line.schedule(firstByte - 1, "an");
    rig.line.schedule(whole - 1, "swer\n");
    const Result<QByteArray> reply = rig.engine.send(request);
    QVERIFY2(reply.ok(), qPrintable(reply.error().message));
    QCOMPARE(*reply, QByteArray("answer"));
    QCOMPARE(rig.line.writes().size(), 1);
}

void TestRequestEngine::fixedTimeoutReplacesTheDerivedOne() {
    Rig rig([](const QByteArray&, int) { return silence(); });
    EngineSettings settings = Rig::settings(9600);
    settings.fixedTimeoutMs = 250;
    rig.engine.setSettings(settings);
    const Request request = query("?x");
    QCOMPARE(rig.engine.attemptTimeoutMs(request), 250);
    QCOMPARE(rig.engine.firstByteTimeoutMs(request), 250);
    QVERIFY(!rig.engine.send(request).ok());
    QCOMPARE(rig.writeGap(1), qint64(250));
    Request own = query("?y");
    own.fixedTimeoutMs = 40;  // the request's own wins
    QCOMPARE(rig.engine.attemptTimeoutMs(own), 40);
}

void TestRequestEngine::idempotentRequestIsRetriedAfterSilence() {
    Rig rig([](const QByteArray&, int index) {
        return index == 0 ? silence() : replyAfter(5, "value");
    });
    const Result<QByteArray> reply = rig.engine.send(query("?x"));
    QVERIFY2(reply.ok(), qPrintable(reply.error().message));
    QCOMPARE(*reply, QByteArray("value"));
    QCOMPARE(rig.line.writes().size(), 2);
    QCOMPARE(rig.line.writes()[1].bytes, rig.line.writes()[0].bytes);  // the same request
    QCOMPARE(rig.engine.lastAttempts(), 2);
    QCOMPARE(rig.engine.stats().retries, 1);
}

void TestRequestEngine::neverRequestIsSentOnceWithoutDeduplication() {
    Rig rig([](const QByteArray&, int) { return silence(); });
    const Result<QByteArray> reply = rig.engine.send(query("!move", RetryPolicy::Never));
    QVERIFY(!reply.ok());
    QCOMPARE(reply.error().kind, ErrorKind::Communication);
    QCOMPARE(rig.line.writes().size(), 1);
    QVERIFY(!rig.engine.lastCallHeardDevice());
}

void TestRequestEngine::neverRequestIsRetriedWhenTheProtocolDeduplicates() {
    Rig rig(
        [](const QByteArray&, int index) { return index < 2 ? silence() : replyAfter(5, "moved"); },
        true);
    const Result<QByteArray> reply = rig.engine.send(query("!move", RetryPolicy::Never));
    QVERIFY2(reply.ok(), qPrintable(reply.error().message));
    QCOMPARE(rig.line.writes().size(), 3);
    // Repeats are answered, not executed: nothing may have acted twice.
    QVERIFY(!rig.engine.lastCallMayHaveActedTwice());
}

void TestRequestEngine::checkAfterRequestIsRetriedAndFlagged() {
    Rig rig([](const QByteArray&, int index) {
        return index == 0 ? silence() : replyAfter(5, "next");
    });
    const Result<QByteArray> reply = rig.engine.send(query("?step", RetryPolicy::CheckAfter));
    QVERIFY2(reply.ok(), qPrintable(reply.error().message));
    QCOMPARE(rig.line.writes().size(), 2);
    QVERIFY(rig.engine.lastCallMayHaveActedTwice());
    // A call answered at once clears the flag.
    QVERIFY(rig.engine.send(query("?step", RetryPolicy::CheckAfter)).ok());
    QVERIFY(!rig.engine.lastCallMayHaveActedTwice());
}

void TestRequestEngine::damagedReplyIsRetriedAtOnce() {
    Rig rig([](const QByteArray&, int index) {
        return replyAfter(7, index == 0 ? "!garbled" : "value");
    });
    const Result<QByteArray> reply = rig.engine.send(query("?x"));
    QVERIFY2(reply.ok(), qPrintable(reply.error().message));
    QCOMPARE(rig.line.writes().size(), 2);
    // The retry went out when the damaged line arrived, not at a timeout.
    QCOMPARE(rig.writeGap(1), qint64(7));
    QCOMPARE(rig.engine.stats().badFrames, 1);
    QVERIFY(rig.engine.lastCallHeardDevice());
}

void TestRequestEngine::foreignFrameIsIgnored() {
    Rig rig([](const QByteArray&, int) {
        return QList<ScriptedReply>{{3, "~someone else\n"}, {6, "value\n"}};
    });
    const Result<QByteArray> reply = rig.engine.send(query("?x"));
    QVERIFY2(reply.ok(), qPrintable(reply.error().message));
    QCOMPARE(*reply, QByteArray("value"));
    QCOMPARE(rig.line.writes().size(), 1);
}

void TestRequestEngine::resendTakesANewSequenceNumber() {
    Rig rig([](const QByteArray&,
               int index) { return replyAfter(5, index == 0 ? "old answer" : "value"); },
            true);
    Request request = query("?x");
    request.judge = [](const QByteArray& reply, QString& problem) {
        if (reply == "value") return Verdict::Accept;
        problem = QStringLiteral("an old answer");
        return Verdict::Resend;
    };
    const Result<QByteArray> reply = rig.engine.send(request);
    QVERIFY2(reply.ok(), qPrintable(reply.error().message));
    QCOMPARE(rig.line.writes().size(), 2);
    QCOMPARE(rig.line.writes()[0].bytes, QByteArray("?x#0\n"));
    QCOMPARE(rig.line.writes()[1].bytes, QByteArray("?x#1\n"));
    QCOMPARE(rig.engine.lastAttempts(), 1);  // not a retry: a new request
}

void TestRequestEngine::lateAnswerToASilentAttemptIsDropped() {
    // No sequence numbers: the first attempt's answer comes just after the
    // retry went out, the retry's own answer later. The next request must
    // get its own answer, not that straggler.
    qint64 late = 0;
    Rig rig([&late](const QByteArray& written, int) {
        if (startsWith(written, "?a")) return replyAfter(late, "a");
        return replyAfter(5, "b");
    });
    const Request first = query("?a");
    late = rig.engine.firstByteTimeoutMs(first) + 10;
    const Result<QByteArray> a = rig.engine.send(first);
    QVERIFY2(a.ok(), qPrintable(a.error().message));
    QCOMPARE(*a, QByteArray("a"));
    const Result<QByteArray> b = rig.engine.send(query("?b"));
    QVERIFY2(b.ok(), qPrintable(b.error().message));
    QCOMPARE(*b, QByteArray("b"));
    QCOMPARE(rig.engine.stats().lateReplies, 1);
}

void TestRequestEngine::longRequestWhoseProbeIsAnsweredFailsTheAttempt() {
    Rig rig([](const QByteArray& written, int) {
        return startsWith(written, "?probe") ? replyAfter(4, "probe-ok") : silence();
    });
    const Result<QByteArray> reply = rig.engine.send(longRequest(RetryPolicy::Never));
    QVERIFY(!reply.ok());
    QVERIFY2(reply.error().message.contains(QLatin1String("answered ?probe")),
             qPrintable(reply.error().message));
    QCOMPARE(rig.engine.stats().probes, 1);
    QCOMPARE(rig.line.writes().size(), 2);  // the request, the probe; no retry
    // The device answered: the request may have acted.
    QVERIFY(rig.engine.lastCallHeardDevice());
    // Well before the longest working time.
    QVERIFY(rig.clock.nowMs < LineTiming().longWorkMs / 10);
}

void TestRequestEngine::longRequestKeepsWaitingWhileTheProbeIsSilent() {
    Rig rig([](const QByteArray& written, int) {
        return startsWith(written, "!long") ? replyAfter(7500, "long-ok") : silence();
    });
    const Result<QByteArray> reply = rig.engine.send(longRequest(RetryPolicy::Never));
    QVERIFY2(reply.ok(), qPrintable(reply.error().message));
    QCOMPARE(*reply, QByteArray("long-ok"));
    QCOMPARE(rig.engine.stats().probes, 2);  // asked at ~3 s and ~6 s: still busy
    QCOMPARE(rig.line.writes().size(), 3);
}

void TestRequestEngine::lateAnswerDuringTheProbeIsAccepted() {
    // The long request's answer comes while the probe waits for its own.
    Rig rig([](const QByteArray& written, int) {
        return startsWith(written, "!long") ? silence() : replyAfter(2, "long-ok");
    });
    const Result<QByteArray> reply = rig.engine.send(longRequest(RetryPolicy::Never));
    QVERIFY2(reply.ok(), qPrintable(reply.error().message));
    QCOMPARE(*reply, QByteArray("long-ok"));
    QCOMPARE(rig.engine.stats().probes, 1);
}

void TestRequestEngine::longRequestIsRepeatedWhenTheProtocolDeduplicates() {
    // Repeats are answered, not executed: no probe, the request itself again.
    Rig rig([](const QByteArray&,
               int index) { return index < 2 ? silence() : replyAfter(5, "long-ok"); },
            true);
    const Request request = longRequest(RetryPolicy::Never);
    const Result<QByteArray> reply = rig.engine.send(request);
    QVERIFY2(reply.ok(), qPrintable(reply.error().message));
    QCOMPARE(rig.engine.stats().probes, 0);
    QCOMPARE(rig.line.writes().size(), 3);
    QCOMPARE(rig.writeGap(1), qint64(rig.engine.attemptTimeoutMs(request)));
    QVERIFY(rig.engine.attemptTimeoutMs(request) >= LineTiming().probeAfterMs);
}

void TestRequestEngine::cancelEndsTheWait() {
    std::atomic_bool cancel{false};
    Rig rig([&cancel](const QByteArray&, int) {
        cancel = true;  // once the request is out
        return silence();
    });
    rig.engine.setCancelFlag(&cancel);
    const Result<QByteArray> reply = rig.engine.send(longRequest(RetryPolicy::Idempotent));
    QVERIFY(!reply.ok());
    QCOMPARE(reply.error().kind, ErrorKind::Cancelled);
    QCOMPARE(rig.line.writes().size(), 1);
    QVERIFY(rig.clock.nowMs <= 20);  // one slice, not the long wait
    // A cancelled engine sends nothing more.
    QCOMPARE(rig.engine.send(query("?x")).error().kind, ErrorKind::Cancelled);
    QCOMPARE(rig.line.writes().size(), 1);
}

void TestRequestEngine::observerHearsStaleAndListenedFrames() {
    Rig rig([](const QByteArray&, int) { return replyAfter(5, "value"); });
    QList<QByteArray> heard;
    rig.engine.setIncomingObserver([&heard](const Incoming& in) { heard.append(in.wire); });
    rig.line.schedule(0, "~stale\n");  // waiting before the request
    QVERIFY(rig.engine.send(query("?x")).ok());
    rig.line.schedule(rig.clock.nowMs + 30, "late\n");
    QVERIFY(rig.engine.listen(50).ok());
    QCOMPARE(heard, (QList<QByteArray>{"~stale\n", "value\n", "late\n"}));
}

void TestRequestEngine::failureMessageNamesAttemptsAndTime() {
    Rig rig([](const QByteArray&, int) { return silence(); });
    const Request request = query("?x");
    const Result<QByteArray> reply = rig.engine.send(request);
    QVERIFY(!reply.ok());
    const QString expected = QStringLiteral(
                                 "no reply from the fake device to ?x on the scripted "
                                 "line after 4 attempts of %1 ms; check the script")
                                 .arg(rig.engine.firstByteTimeoutMs(request));
    QCOMPARE(reply.error().message, expected);
}

QTEST_GUILESS_MAIN(TestRequestEngine)
#include "tst_request_engine.moc"

// Issue 35 item 9: answers that carry nothing of their request (the
// Compax3's), late by 150 ms, 400 ms and 1 s, while the first-byte time is
// about 0.1 s: every request gets its own answer or fails, never another's.
void TestRequestEngine::aLateAnswerIsItsOwnRequests_data() {
    QTest::addColumn<int>("delayMs");
    QTest::newRow("150 ms") << 150;
    QTest::newRow("400 ms") << 400;
    QTest::newRow("1 s") << 1000;
}

void TestRequestEngine::aLateAnswerIsItsOwnRequests() {
    QFETCH(int, delayMs);
    // Each request is answered with its own name, `delayMs` after it.
    Rig rig([delayMs](const QByteArray& written, int) {
        return replyAfter(delayMs, written.left(written.indexOf('#')).mid(1));
    });
    rig.backend.lateWindowMs = 1000;
    const QList<QByteArray> names = {"serial", "position", "status", "error", "set"};
    for (const QByteArray& name : names) {
        const Result<QByteArray> reply = rig.engine.send(query('?' + name));
        QVERIFY2(reply.ok(), qPrintable(reply.error().message));
        QCOMPARE(*reply, name);
    }
    // Each taken in the wait after its first attempt: nothing sent twice.
    QCOMPARE(rig.line.writes().size(), names.size());
    QCOMPARE(rig.engine.stats().lateAnswersTaken, int(names.size()));
    QVERIFY(rig.engine.firstByteTimeoutMs(query("?serial")) < delayMs);
    // The next request leaves only after the answer: one at a time.
    for (int i = 1; i < names.size(); ++i) QVERIFY(rig.writeGap(i) >= delayMs);
}

void TestRequestEngine::anAnswerAfterAnUnheardAttemptSettlesTheLineFirst() {
    // The first attempt's answer is lost; the second's comes late, but
    // within its window. Which attempt it answered cannot be told, so the
    // next request waits until the line has been quiet for the window.
    Rig rig([](const QByteArray& written, int index) {
        if (index == 0) return silence();
        return replyAfter(300, written.left(written.indexOf('#')).mid(1));
    });
    rig.backend.lateWindowMs = 1000;
    const Result<QByteArray> a = rig.engine.send(query("?a"));
    QVERIFY2(a.ok(), qPrintable(a.error().message));
    QCOMPARE(*a, QByteArray("a"));
    QCOMPARE(rig.line.writes().size(), 2);
    const qint64 answered = rig.clock.nowMs;
    const Result<QByteArray> b = rig.engine.send(query("?b"));
    QCOMPARE(*b, QByteArray("b"));
    QCOMPARE(rig.engine.stats().settles, 1);
    QVERIFY(rig.line.writes().at(2).atMs >= answered + 1000);
}

void TestRequestEngine::aLineWithoutSilenceWaitsNoLonger() {
    // The window costs nothing while every attempt is answered in time:
    // the same writes at the same (virtual) times as without one.
    auto script = [](const QByteArray&, int) { return replyAfter(5, "value"); };
    Rig plain(script);
    Rig windowed(script);
    windowed.backend.lateWindowMs = 1000;
    for (int i = 0; i < 20; ++i) {
        QVERIFY(plain.engine.send(query("?x")).ok());
        QVERIFY(windowed.engine.send(query("?x")).ok());
    }
    QCOMPARE(windowed.line.writes().size(), plain.line.writes().size());
    for (int i = 0; i < plain.line.writes().size(); ++i)
        QCOMPARE(windowed.line.writes().at(i).atMs, plain.line.writes().at(i).atMs);
    QCOMPARE(windowed.clock.nowMs, plain.clock.nowMs);
    QCOMPARE(windowed.engine.stats().lateAnswerWaits, 0);
    QCOMPARE(windowed.engine.stats().settles, 0);
}

void TestRequestEngine::aShortLookStaysShortAndTheNextRequestWaitsForQuiet() {
    // A bus scan's look at an empty address stays short; what it may still
    // hear later is not taken by the next real request.
    Rig rig([](const QByteArray& written, int) {
        return startsWith(written, "?look") ? replyAfter(400, "look") : replyAfter(5, "value");
    });
    rig.backend.lateWindowMs = 1000;
    Request look = query("?look");
    look.maxAttempts = 1;
    look.silenceExpected = true;
    look.turnaroundMs = 30;
    QVERIFY(!rig.engine.send(look).ok());
    QVERIFY(rig.clock.nowMs < 100);
    const Result<QByteArray> value = rig.engine.send(query("?x"));
    QVERIFY2(value.ok(), qPrintable(value.error().message));
    QCOMPARE(*value, QByteArray("value"));
    QCOMPARE(rig.engine.stats().settles, 1);
    QCOMPARE(rig.engine.stats().lateReplies, 1);  // "look", dropped
}
