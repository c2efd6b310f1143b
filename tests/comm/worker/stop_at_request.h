#pragma once

// Issue 35: a STOP that lands inside a chosen step of a job, deterministic
// (no sleeping): the job's N-th request leaves, and at that moment the STOP
// is asked exactly as the GUI asks it (the line's STOP generation raised,
// what waits for the line dropped, the STOP's Urgent job submitted). The
// STOP's job then runs between two requests of the job, as it does on a
// real line. Every request that leaves, the job's and the STOP's, is logged
// in order through the engine's request gate, and the log is checked
// against the telegrams on the wire (the traffic the worker reports).
// Names no family: the families' tests bring their jobs.

#include "comm/device/job_runner.h"
#include "comm/device/motion_control.h"
#include "comm/engine/request_engine.h"

#include <QObject>
#include <QTest>

#include <algorithm>
#include <memory>
#include <mutex>
#include <optional>

namespace cambench::comm::test {

// One request that left, in the order they left.
struct LeftRequest {
    QString label;
    QByteArray message;
    bool motion = false;     // Request::motion, as the family code set it
    bool fromStop = false;   // the STOP's own job sent it
    bool afterStop = false;  // sent after the STOP was asked
};

template <class T>
struct StopRun {
    std::optional<Result<T>> result;  // the job's
    std::optional<MotionStopReport> stop;
    QList<LeftRequest> left;
    int wireRequests = 0;  // outgoing traffic entries
    bool stopAsked = false;
};

namespace detail {

struct StopLog {
    std::mutex mutex;
    QList<LeftRequest> left;
    bool stopAsked = false;
    void add(const Request& request, bool fromStop) {
        std::lock_guard lock(mutex);
        left << LeftRequest{request.label, request.message, request.motion, fromStop, stopAsked};
    }
};

}  // namespace detail

// Runs `work` as a User job on `worker` (connected) and asks a STOP of
// every motion right after the job's `stopAfter`-th request has left
// (0: before its first request; past its last: never). Waits for the job
// and the STOP.
template <class T>
StopRun<T> runWithStopAfter(JobRunner& worker, int stopAfter,
                            std::function<Result<T>(JobContext&)> work, int waitMs = 60000) {
    auto log = std::make_shared<detail::StopLog>();
    StopRun<T> run;
    QObject context;
    int wire = 0;
    const QMetaObject::Connection traffic =
        QObject::connect(&worker, &JobRunner::traffic, &context, [&wire](const TrafficEntry& e) {
            if (e.outgoing) ++wire;
        });
    JobRunner* runner = &worker;
    const auto askStop = [runner, log, &context, &run] {
        {
            std::lock_guard lock(log->mutex);
            log->stopAsked = true;
        }
        runner->raiseStopGeneration();
        runner->dropQueued();
        runner->run<MotionStopReport>(
            &context, JobPriority::Urgent, QStringLiteral("STOP"),
            [log](JobContext& job) {
                MotionStopReport report;
                MotionControl* motion = job.device() ? job.device()->motionControl() : nullptr;
                if (!motion) return report;
                RequestEngine& engine = job.device()->engine();
                engine.setRequestGate([log](const Request& request) {
                    log->add(request, true);
                    return QString();
                });
                report = motion->stopAllMotion();
                engine.setRequestGate({});
                return report;
            },
            [&run](MotionStopReport report) { run.stop = std::move(report); });
    };
    worker.run<Result<T>>(
        &context, JobPriority::User, QStringLiteral("job under test"),
        [log, stopAfter, askStop, work = std::move(work)](JobContext& job) -> Result<T> {
            if (!job.device()) return work(job);
            RequestEngine& engine = job.device()->engine();
            auto count = std::make_shared<int>(0);
            if (stopAfter == 0) askStop();
            engine.setRequestGate([log, count, stopAfter, askStop](const Request& request) {
                log->add(request, false);
                if (++*count == stopAfter) askStop();
                return QString();
            });
            Result<T> result = work(job);
            engine.setRequestGate({});
            return result;
        },
        [&run](Result<T> result) { run.result = std::move(result); });
    const bool done = QTest::qWaitFor(
        [&run, log] {
            std::lock_guard lock(log->mutex);
            return run.result.has_value() && (!log->stopAsked || run.stop.has_value());
        },
        waitMs);
    // Every traffic entry comes before the job's answer; one more turn of the
    // event loop for the last ones.
    QTest::qWait(0);
    QObject::disconnect(traffic);
    if (!done) return run;
    std::lock_guard lock(log->mutex);
    run.left = log->left;
    run.stopAsked = log->stopAsked;
    run.wireRequests = wire;
    return run;
}

// A motion job to stop inside each of its steps.
struct MotionJobUnderTest {
    QString name;
    // A worker on a fresh device, connected and set up for the job.
    std::function<std::unique_ptr<JobRunner>()> connect;
    // The job; its outcome as text (an error: the job's error).
    std::function<Result<QString>(JobContext&)> work;
    // Whether a request moves something or writes, told from its bytes as
    // the manual says (not by the code under test).
    std::function<bool(const QByteArray&)> movesOrWrites;
};

// The rows of a test that runs once per motion job: column "job", its index.
inline void motionJobRows(const QList<MotionJobUnderTest>& jobs) {
    QTest::addColumn<int>("job");
    for (int i = 0; i < jobs.size(); ++i) QTest::newRow(qPrintable(jobs.at(i).name)) << i;
}

// Runs `job` without a STOP, then once with a STOP after each of its
// requests (and before the first): no request of the job that moves or
// writes leaves after the STOP; where the job had not moved yet it ends
// "stopped before it moved" and sends nothing after its refused request;
// the STOP's own requests neither move nor write (they stop); every
// telegram on the wire is one of the logged requests.
inline void stopInsideEveryStep(const MotionJobUnderTest& job) {
    std::unique_ptr<JobRunner> plain = job.connect();
    QVERIFY(plain);
    const StopRun<QString> baseline = runWithStopAfter<QString>(*plain, 1 << 20, job.work);
    QVERIFY2(baseline.result && baseline.result->ok(),
             qPrintable(baseline.result ? baseline.result->error().message : "no answer"));
    QList<int> moving;  // 1-based request numbers
    for (int i = 0; i < baseline.left.size(); ++i) {
        const LeftRequest& sent = baseline.left.at(i);
        // The family code marks exactly the requests whose bytes move.
        QVERIFY2(sent.motion == job.movesOrWrites(sent.message), qPrintable(sent.label));
        if (sent.motion) moving << i + 1;
    }
    QVERIFY(!moving.isEmpty());
    QCOMPARE(baseline.wireRequests, baseline.left.size());

    for (int stopAfter = 0; stopAfter <= baseline.left.size(); ++stopAfter) {
        const QString step = QStringLiteral("%1, STOP after request %2 of %3")
                                 .arg(job.name)
                                 .arg(stopAfter)
                                 .arg(baseline.left.size());
        std::unique_ptr<JobRunner> worker = job.connect();
        QVERIFY2(worker, qPrintable(step));
        const StopRun<QString> run = runWithStopAfter<QString>(*worker, stopAfter, job.work);
        QVERIFY2(run.result && run.stop, qPrintable(step));
        QVERIFY2(run.wireRequests == run.left.size(), qPrintable(step));
        QList<LeftRequest> own;
        for (const LeftRequest& sent : run.left) {
            if (sent.fromStop) continue;
            QVERIFY2(!sent.afterStop || !job.movesOrWrites(sent.message),
                     qPrintable(step + QStringLiteral(": ") + sent.label));
            own << sent;
        }
        const auto next = std::find_if(moving.begin(), moving.end(),
                                       [stopAfter](int n) { return n > stopAfter; });
        if (next == moving.end()) continue;  // it had moved before the STOP
        // Stopped at its next motion: what it sent is what it sends up to there.
        QVERIFY2(own.size() == *next - 1, qPrintable(step));
        for (int i = 0; i < own.size(); ++i)
            QVERIFY2(own.at(i).message == baseline.left.at(i).message, qPrintable(step));
        const QString outcome =
            run.result->ok() ? run.result->value() : run.result->error().message;
        QVERIFY2(outcome.contains(QLatin1String("stopped before it moved: STOP at ")),
                 qPrintable(step + QStringLiteral(": ") + outcome));
        QVERIFY2(run.result->ok() || run.result->error().kind == ErrorKind::Cancelled,
                 qPrintable(step));
    }
}

}  // namespace cambench::comm::test
