// CommWorker with real transports: the in-process simulator for queueing,
// a pseudo-terminal (QSerialPort) for cancelling and a vanishing port.
#include "../link/pty_device.h"

#include "comm/camcon/ascii/ascii_camcon.h"
#include "comm/camcon/ascii/ascii_protocol.h"
#include "comm/traffic/traffic_log.h"
#include "comm/worker/comm_worker.h"

#include <QSemaphore>
#include <QSignalSpy>
#include <QtTest>

#include <memory>
#include <mutex>
#include <optional>

using namespace cambench;
using namespace cambench::comm;
using namespace cambench::comm::test;

namespace {

constexpr int kHangBoundMs = 20000;  // bounds a hang; never a speed check

ProtocolSettingsPtr linkSettings(int timeoutMs, int retries = 0) {
    return std::make_shared<AsciiProtocolSettings>(
        AsciiSettings{Framing::Standard, 0, 63, timeoutMs, 150000, retries});
}

// ?UNIT to the connected CamCon (Standard framing) through its ASCII link.
Result<Fields> askUnit(JobContext& ctx) {
    Result<AsciiCamCon*> device = ctx.family<AsciiCamCon>();
    if (!device) return device.error();
    return (*device)->link().call('?', "UNIT");
}

ConnectionSettings portSettings(const QString& port) {
    return ConnectionSettings{port, SerialSettings{}, {}};
}

// Records job titles in the order they run, from the worker thread.
struct RunLog {
    std::mutex mutex;
    QStringList titles;
    void add(const QString& title) {
        std::lock_guard lock(mutex);
        titles.append(title);
    }
    QStringList get() {
        std::lock_guard lock(mutex);
        return titles;
    }
};

}  // namespace

class TestCommWorker : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void connectingReportsConnectingThenConnected();
    void connectFailureReportsDisconnectedWithMessage();
    void jobRunsOnWorkerThread();
    void jobCallsReachTheDevice();
    void jobWithoutConnectionFailsWithNotConnected();
    void userJobsRunBeforePollJobs();
    void pollWithSameKeyReplacesQueuedPoll();
    void cancelQueuedJobRemovesIt();
    void cancelRunningJobReturnsCancelled();
    void cancelAllStopsEverything();
    void jobAfterDisconnectRunsAfterIt();
    void jobProgressAndTrafficReachTheFront();
    void vanishingPortMakesStateLostAndLaterJobsFailFast();
    void reconnectAfterLostWorks();
    void destructorReturnsWhileJobRuns();
    void urgentJobRunsBeforeQueuedJobs();
    void urgentJobRunsBetweenTwoRequestsOfARunningJob();
    void dropQueuedLeavesTheRunningJobAlone();
    void aJobDroppedByStopEndsAsNotSent();

private:
    // Submits a User job that holds the worker until `gate` is released.
    quint64 submitBlocker(CommWorker& worker, QSemaphore& gate, RunLog& log);
    // The same, once the blocker runs; 0 when it did not start.
    quint64 holdWorker(CommWorker& worker, QSemaphore& gate, RunLog& log);
};

quint64 TestCommWorker::submitBlocker(CommWorker& worker, QSemaphore& gate, RunLog& log) {
    return worker.submit(JobPriority::User, "blocker", [&gate, &log](JobContext&) {
        log.add("blocker");
        gate.acquire();
    });
}

quint64 TestCommWorker::holdWorker(CommWorker& worker, QSemaphore& gate, RunLog& log) {
    const quint64 blocker = submitBlocker(worker, gate, log);
    return QTest::qWaitFor([&log] { return log.get().size() == 1; }, kHangBoundMs) ? blocker : 0;
}

void TestCommWorker::connectingReportsConnectingThenConnected() {
    CommWorker worker;
    QSignalSpy states(&worker, &CommWorker::connectionStateChanged);
    worker.connectTo(portSettings("sim"), linkSettings(1000));
    QTRY_COMPARE_WITH_TIMEOUT(states.size(), 2, kHangBoundMs);
    QCOMPARE(states[0][0].value<ConnectionState>(), ConnectionState::Connecting);
    QCOMPARE(states[1][0].value<ConnectionState>(), ConnectionState::Connected);
    QCOMPARE(worker.state(), ConnectionState::Connected);
}

void TestCommWorker::connectFailureReportsDisconnectedWithMessage() {
    CommWorker worker;
    QSignalSpy states(&worker, &CommWorker::connectionStateChanged);
    worker.connectTo(portSettings("/dev/cambench-no-such-port"), linkSettings(1000));
    QTRY_COMPARE_WITH_TIMEOUT(states.size(), 2, kHangBoundMs);
    QCOMPARE(states[1][0].value<ConnectionState>(), ConnectionState::Disconnected);
    QVERIFY(states[1][1].toString().contains("/dev/cambench-no-such-port"));
    QCOMPARE(worker.state(), ConnectionState::Disconnected);
}

void TestCommWorker::jobRunsOnWorkerThread() {
    CommWorker worker;
    std::optional<QThread*> jobThread;
    QThread* doneThread = nullptr;
    worker.run<QThread*>(
        this, JobPriority::User, "where", [](JobContext&) { return QThread::currentThread(); },
        [&](QThread* thread) {
            jobThread = thread;
            doneThread = QThread::currentThread();
        });
    QTRY_VERIFY_WITH_TIMEOUT(jobThread.has_value(), kHangBoundMs);
    QVERIFY(*jobThread != QThread::currentThread());
    QCOMPARE(doneThread, QThread::currentThread());  // results come back to the context
}

void TestCommWorker::jobCallsReachTheDevice() {
    CommWorker worker;
    worker.connectTo(portSettings("sim:throttle=0"), linkSettings(1000, 2));
    std::optional<Result<Fields>> reply;
    worker.run<Result<Fields>>(
        this, JobPriority::User, "unit", [](JobContext& ctx) { return askUnit(ctx); },
        [&](Result<Fields> result) { reply = std::move(result); });
    QTRY_VERIFY_WITH_TIMEOUT(reply.has_value(), kHangBoundMs);
    QVERIFY2(reply->ok(), qPrintable(reply->error().message));
}

void TestCommWorker::jobWithoutConnectionFailsWithNotConnected() {
    CommWorker worker;
    std::optional<Result<Fields>> reply;
    worker.run<Result<Fields>>(
        this, JobPriority::User, "unit", [](JobContext& ctx) { return askUnit(ctx); },
        [&](Result<Fields> result) { reply = std::move(result); });
    QTRY_VERIFY_WITH_TIMEOUT(reply.has_value(), kHangBoundMs);
    QVERIFY(!reply->ok());
    QCOMPARE(reply->error().kind, ErrorKind::Communication);
    QVERIFY2(reply->error().message.contains("not connected"), qPrintable(reply->error().message));
}

void TestCommWorker::userJobsRunBeforePollJobs() {
    CommWorker worker;
    QSemaphore gate;
    RunLog log;
    QSignalSpy finished(&worker, &CommWorker::jobFinished);
    submitBlocker(worker, gate, log);
    QTRY_COMPARE_WITH_TIMEOUT(log.get().size(), 1, kHangBoundMs);
    for (const char* title : {"poll 1", "user 1", "poll 2", "user 2"}) {
        const JobPriority priority =
            QByteArray(title).startsWith("user") ? JobPriority::User : JobPriority::Poll;
        worker.submit(priority, title, [&log, title](JobContext&) { log.add(title); });
    }
    gate.release();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 5, kHangBoundMs);
    QCOMPARE(log.get(), QStringList({"blocker", "user 1", "user 2", "poll 1", "poll 2"}));
}

void TestCommWorker::pollWithSameKeyReplacesQueuedPoll() {
    CommWorker worker;
    QSemaphore gate;
    RunLog log;
    QSignalSpy finished(&worker, &CommWorker::jobFinished);
    submitBlocker(worker, gate, log);
    QTRY_COMPARE_WITH_TIMEOUT(log.get().size(), 1, kHangBoundMs);
    QList<quint64> ids;
    for (const char* title : {"status 1", "status 2", "status 3"})
        ids.append(worker.submit(
            JobPriority::Poll, title, [&log, title](JobContext&) { log.add(title); }, "status"));
    gate.release();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 4, kHangBoundMs);
    QCOMPARE(log.get(), QStringList({"blocker", "status 3"}));
    // Every id finishes once, the replaced ones too.
    QList<quint64> finishedIds;
    for (const auto& args : finished) finishedIds.append(args[0].toULongLong());
    for (const quint64 id : ids) QCOMPARE(finishedIds.count(id), 1);
}

void TestCommWorker::cancelQueuedJobRemovesIt() {
    CommWorker worker;
    QSemaphore gate;
    RunLog log;
    QSignalSpy finished(&worker, &CommWorker::jobFinished);
    submitBlocker(worker, gate, log);
    QTRY_COMPARE_WITH_TIMEOUT(log.get().size(), 1, kHangBoundMs);
    const quint64 victim =
        worker.submit(JobPriority::User, "victim", [&log](JobContext&) { log.add("victim"); });
    worker.submit(JobPriority::User, "after", [&log](JobContext&) { log.add("after"); });
    worker.cancel(victim);
    gate.release();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 3, kHangBoundMs);
    QCOMPARE(log.get(), QStringList({"blocker", "after"}));
    QList<quint64> finishedIds;
    for (const auto& args : finished) finishedIds.append(args[0].toULongLong());
    QVERIFY(finishedIds.contains(victim));
}

void TestCommWorker::cancelRunningJobReturnsCancelled() {
    PtyDevice device(Framing::Standard, [](const Frame&, int) { return DeviceAction{}; });
    QVERIFY(device.isValid());
    CommWorker worker;
    worker.connectTo(portSettings(device.slavePath()), linkSettings(120000));
    std::optional<Result<Fields>> reply;
    const quint64 id = worker.run<Result<Fields>>(
        this, JobPriority::User, "silent", [](JobContext& ctx) { return askUnit(ctx); },
        [&](Result<Fields> result) { reply = std::move(result); });
    // Only a working cancel ends the wait: the device never answers.
    QTRY_COMPARE_WITH_TIMEOUT(device.requestCount(), 1, kHangBoundMs);
    worker.cancel(id);
    QTRY_VERIFY_WITH_TIMEOUT(reply.has_value(), kHangBoundMs);
    QVERIFY(!reply->ok());
    QCOMPARE(reply->error().kind, ErrorKind::Cancelled);
    QCOMPARE(worker.state(), ConnectionState::Connected);
}

void TestCommWorker::cancelAllStopsEverything() {
    PtyDevice device(Framing::Standard, [](const Frame&, int) { return DeviceAction{}; });
    CommWorker worker;
    worker.connectTo(portSettings(device.slavePath()), linkSettings(120000));
    RunLog log;
    QSignalSpy finished(&worker, &CommWorker::jobFinished);
    std::optional<ErrorKind> kind;
    worker.submit(JobPriority::User, "silent",
                  [&kind](JobContext& ctx) { kind = askUnit(ctx).error().kind; });
    worker.submit(JobPriority::User, "queued", [&log](JobContext&) { log.add("queued"); });
    worker.submit(
        JobPriority::Poll, "poll", [&log](JobContext&) { log.add("poll"); }, "p");
    QTRY_COMPARE_WITH_TIMEOUT(device.requestCount(), 1, kHangBoundMs);
    worker.cancelAll();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 3, kHangBoundMs);
    QCOMPARE(kind, ErrorKind::Cancelled);
    QVERIFY(log.get().isEmpty());
}

// Jobs cancelled while queued leave their calls behind in the worker's
// event queue; none of those may run a job submitted after a disconnect
// before the disconnect itself (Detect opens the port itself right after).
void TestCommWorker::jobAfterDisconnectRunsAfterIt() {
    CommWorker worker;
    worker.connectTo(portSettings("sim"), linkSettings(1000));
    QTRY_COMPARE_WITH_TIMEOUT(worker.state(), ConnectionState::Connected, kHangBoundMs);
    QSemaphore gate;
    RunLog log;
    submitBlocker(worker, gate, log);
    for (int i = 0; i < 5; ++i)
        worker.submit(JobPriority::User, "queued", [&log](JobContext&) { log.add("queued"); });
    QTRY_COMPARE_WITH_TIMEOUT(log.get().size(), 1, kHangBoundMs);  // the blocker runs
    worker.cancelAll();
    worker.disconnectFromDevice();
    std::optional<bool> answered;
    worker.submit(JobPriority::User, "after", [&answered](JobContext& ctx) {
        answered = askUnit(ctx).ok();  // the line must be gone by now
    });
    gate.release();
    QTRY_VERIFY_WITH_TIMEOUT(answered.has_value(), kHangBoundMs);
    QCOMPARE(*answered, false);
}

void TestCommWorker::jobProgressAndTrafficReachTheFront() {
    CommWorker worker;
    worker.connectTo(portSettings("sim:throttle=0"), linkSettings(1000, 2));
    QSignalSpy started(&worker, &CommWorker::jobStarted);
    QSignalSpy progress(&worker, &CommWorker::jobProgress);
    QSignalSpy finished(&worker, &CommWorker::jobFinished);
    QSignalSpy traffic(&worker, &CommWorker::traffic);
    const quint64 id = worker.submit(JobPriority::User, "two steps", [](JobContext& ctx) {
        ctx.progress(1, 2, "first");
        askUnit(ctx);
        ctx.progress(2, 2, "second");
    });
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, kHangBoundMs);
    QCOMPARE(started.size(), 1);
    QCOMPARE(started[0][0].toULongLong(), id);
    QCOMPARE(started[0][1].toString(), QStringLiteral("two steps"));
    QCOMPARE(progress.size(), 2);
    QCOMPARE(progress[1][1].toLongLong(), 2);
    QCOMPARE(progress[1][3].toString(), QStringLiteral("second"));
    QCOMPARE(traffic.size(), 2);
    const auto request = traffic[0][0].value<TrafficEntry>();
    QVERIFY(request.outgoing);
    QVERIFY(formatTrafficEntry(request).contains("|?UNIT"));
    QVERIFY(!traffic[1][0].value<TrafficEntry>().outgoing);
}

void TestCommWorker::vanishingPortMakesStateLostAndLaterJobsFailFast() {
    PtyDevice device(Framing::Standard, [](const Frame&, int) {
        return DeviceAction{{}, 0, true};
    });
    CommWorker worker;
    QSignalSpy states(&worker, &CommWorker::connectionStateChanged);
    worker.connectTo(portSettings(device.slavePath()), linkSettings(60000, 3));
    QTRY_COMPARE_WITH_TIMEOUT(worker.state(), ConnectionState::Connected, kHangBoundMs);

    std::optional<Result<Fields>> first;
    worker.run<Result<Fields>>(
        this, JobPriority::User, "unit", [](JobContext& ctx) { return askUnit(ctx); },
        [&](Result<Fields> result) { first = std::move(result); });
    QTRY_VERIFY_WITH_TIMEOUT(first.has_value(), kHangBoundMs);
    QVERIFY(!first->ok());
    QCOMPARE(first->error().kind, ErrorKind::Communication);
    QVERIFY2(first->error().message.contains(device.slavePath()),
             qPrintable(first->error().message));

    QTRY_COMPARE_WITH_TIMEOUT(worker.state(), ConnectionState::Lost, kHangBoundMs);
    QCOMPARE(states.last()[0].value<ConnectionState>(), ConnectionState::Lost);
    QVERIFY2(states.last()[1].toString().contains("disappeared"),
             qPrintable(states.last()[1].toString()));

    std::optional<Result<Fields>> second;
    worker.run<Result<Fields>>(
        this, JobPriority::User, "unit again", [](JobContext& ctx) { return askUnit(ctx); },
        [&](Result<Fields> result) { second = std::move(result); });
    QTRY_VERIFY_WITH_TIMEOUT(second.has_value(), kHangBoundMs);
    QVERIFY(!second->ok());
    QCOMPARE(second->error().kind, ErrorKind::Communication);
    QVERIFY2(second->error().message.contains("not connected"),
             qPrintable(second->error().message));
    QCOMPARE(device.requestCount(), 1);
}

void TestCommWorker::reconnectAfterLostWorks() {
    PtyDevice vanishing(Framing::Standard, [](const Frame&, int) {
        return DeviceAction{{}, 0, true};
    });
    PtyDevice healthy(Framing::Standard, [](const Frame& request, int) {
        return DeviceAction{{replyTo(request, "UNIT")}};
    });
    CommWorker worker;
    worker.connectTo(portSettings(vanishing.slavePath()), linkSettings(60000));
    worker.submit(JobPriority::User, "lose it", [](JobContext& ctx) { askUnit(ctx); });
    QTRY_COMPARE_WITH_TIMEOUT(worker.state(), ConnectionState::Lost, kHangBoundMs);

    worker.connectTo(portSettings(healthy.slavePath()), linkSettings(5000));
    QTRY_COMPARE_WITH_TIMEOUT(worker.state(), ConnectionState::Connected, kHangBoundMs);
    std::optional<Result<Fields>> reply;
    worker.run<Result<Fields>>(
        this, JobPriority::User, "unit", [](JobContext& ctx) { return askUnit(ctx); },
        [&](Result<Fields> result) { reply = std::move(result); });
    QTRY_VERIFY_WITH_TIMEOUT(reply.has_value(), kHangBoundMs);
    QVERIFY2(reply->ok(), qPrintable(reply->error().message));
}

void TestCommWorker::destructorReturnsWhileJobRuns() {
    PtyDevice device(Framing::Standard, [](const Frame&, int) { return DeviceAction{}; });
    auto worker = std::make_unique<CommWorker>();
    worker->connectTo(portSettings(device.slavePath()), linkSettings(120000, 3));
    std::atomic_bool jobReturned{false};
    worker->submit(JobPriority::User, "silent", [&jobReturned](JobContext& ctx) {
        askUnit(ctx);
        jobReturned = true;
    });
    QTRY_COMPARE_WITH_TIMEOUT(device.requestCount(), 1, kHangBoundMs);
    worker.reset();  // must cancel the job and stop the thread, not wait 8 minutes
    QVERIFY(jobReturned.load());
}

void TestCommWorker::urgentJobRunsBeforeQueuedJobs() {
    CommWorker worker;
    QSemaphore gate;
    RunLog log;
    QVERIFY(holdWorker(worker, gate, log) != 0);
    QSignalSpy finished(&worker, &CommWorker::jobFinished);
    worker.submit(JobPriority::Poll, "poll", [&log](JobContext&) { log.add("poll"); });
    worker.submit(JobPriority::User, "user", [&log](JobContext&) { log.add("user"); });
    worker.submit(JobPriority::Urgent, "stop", [&log](JobContext&) { log.add("stop"); });
    gate.release();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 4, kHangBoundMs);  // the blocker too
    QCOMPARE(log.get(), QStringList({"blocker", "stop", "user", "poll"}));
}

// A long job (a backup) is paused for a STOP between two of its requests,
// not broken and not waited for; jobs queued before the STOP still wait
// for the long job's end.
void TestCommWorker::urgentJobRunsBetweenTwoRequestsOfARunningJob() {
    CommWorker worker;
    worker.connectTo(portSettings("sim:throttle=0"), linkSettings(1000, 2));
    QSemaphore gate;
    RunLog log;
    QSignalSpy finished(&worker, &CommWorker::jobFinished);
    constexpr int kRequests = 6;
    worker.submit(JobPriority::User, "backup", [&gate, &log](JobContext& ctx) {
        for (int request = 1; request <= kRequests; ++request) {
            const Result<Fields> unit = askUnit(ctx);
            log.add(QStringLiteral("backup %1 %2").arg(request).arg(unit ? "ok" : "failed"));
            if (request == 3) gate.acquire();  // the test submits the STOP here
        }
    });
    QTRY_COMPARE_WITH_TIMEOUT(log.get().size(), 3, kHangBoundMs);
    worker.submit(JobPriority::User, "queued", [&log](JobContext&) { log.add("queued"); });
    worker.submit(JobPriority::Urgent, "stop", [&log](JobContext& ctx) {
        // Its own request does not run it again.
        const Result<Fields> unit = askUnit(ctx);
        log.add(QStringLiteral("stop %1").arg(unit ? "ok" : "failed"));
    });
    gate.release();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 3, kHangBoundMs);
    QCOMPARE(log.get(), QStringList({"backup 1 ok", "backup 2 ok", "backup 3 ok", "stop ok",
                                     "backup 4 ok", "backup 5 ok", "backup 6 ok", "queued"}));
}

void TestCommWorker::dropQueuedLeavesTheRunningJobAlone() {
    CommWorker worker;
    QSemaphore gate;
    RunLog log;
    QSignalSpy finished(&worker, &CommWorker::jobFinished);
    const quint64 blocker = holdWorker(worker, gate, log);
    QVERIFY(blocker != 0);
    const quint64 move =
        worker.submit(JobPriority::User, "move", [&log](JobContext&) { log.add("move"); });
    worker.submit(JobPriority::Urgent, "stop", [&log](JobContext& ctx) {
        log.add(ctx.cancelled() ? "stop cancelled" : "stop");
    });
    worker.dropQueued();
    gate.release();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 3, kHangBoundMs);
    QCOMPARE(log.get(), QStringList({"blocker", "stop"}));
    QList<quint64> ids;
    for (const QList<QVariant>& args : finished) ids << args.first().toULongLong();
    QVERIFY(ids.contains(move));  // a dropped job still finishes
    QVERIFY(ids.contains(blocker));
}

// A caller waiting for a queued job hears that a STOP dropped it: once,
// Cancelled, "not sent", and its work never ran (the running job goes on).
void TestCommWorker::aJobDroppedByStopEndsAsNotSent() {
    CommWorker worker;
    QSemaphore gate;
    RunLog log;
    QSignalSpy finished(&worker, &CommWorker::jobFinished);
    QVERIFY(holdWorker(worker, gate, log) != 0);
    QObject context;
    QList<Result<int>> moveDone;
    QList<Result<int>> pollDone;
    worker.run<Result<int>>(
        &context, JobPriority::User, "move",
        [&log](JobContext&) -> Result<int> {
            log.add("move");
            return 1;
        },
        [&moveDone](Result<int> result) { moveDone << result; });
    worker.run<Result<int>>(
        &context, JobPriority::Poll, "poll",
        [&log](JobContext&) -> Result<int> {
            log.add("poll");
            return 2;
        },
        [&pollDone](Result<int> result) { pollDone << result; }, QStringLiteral("poll"));
    worker.dropQueued();
    gate.release();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 3, kHangBoundMs);
    QTRY_COMPARE_WITH_TIMEOUT(moveDone.size() + pollDone.size(), 2, kHangBoundMs);
    QCOMPARE(log.get(), QStringList({"blocker"}));
    for (const QList<Result<int>>* done : {&moveDone, &pollDone}) {
        QCOMPARE(done->size(), 1);
        QVERIFY(!done->first().ok());
        QCOMPARE(done->first().error().kind, ErrorKind::Cancelled);
        QCOMPARE(done->first().error().message, QStringLiteral("not sent: dropped by STOP"));
    }
}

QTEST_GUILESS_MAIN(TestCommWorker)
#include "tst_comm_worker.moc"
