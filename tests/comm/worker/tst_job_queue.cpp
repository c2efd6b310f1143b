#include "comm/worker/job_queue.h"

#include <QtTest>

using namespace cambench::comm;

namespace {

// The titles in the order the queue hands the jobs out.
QStringList drain(JobQueue& queue) {
    QStringList titles;
    while (auto job = queue.takeNext()) {
        titles.append(job->title);
        queue.finishRunning();
    }
    return titles;
}

}  // namespace

class TestJobQueue : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void userJobsComeBeforePollJobs();
    void pollWithSameKeyReplacesQueuedPoll();
    void pollKeysOnlyCollapseEqualKeys();
    void userJobsNeverCollapse();
    void cancelRemovesQueuedJob();
    void cancelSignalsRunningJob();
    void cancelUnknownIdChangesNothing();
    void cancelAllEmptiesQueueAndSignalsRunningJob();
    void urgentJobsComeFirst();
    void urgentJobTakenWhileAnotherRunsLeavesItRunning();
    void dropQueuedKeepsUrgentAndRunningJobs();
    void motionIsPushedOnlyWhenTheLineIsFree();
    void aJobRecordsTheStopGenerationItWasAskedIn();
};

void TestJobQueue::userJobsComeBeforePollJobs() {
    JobQueue queue;
    queue.push(JobPriority::Poll, "p1", {});
    queue.push(JobPriority::User, "u1", {});
    queue.push(JobPriority::Poll, "p2", {});
    queue.push(JobPriority::User, "u2", {});
    QCOMPARE(drain(queue), QStringList({"u1", "u2", "p1", "p2"}));
}

void TestJobQueue::pollWithSameKeyReplacesQueuedPoll() {
    JobQueue queue;
    const auto first = queue.push(JobPriority::Poll, "status 1", {}, "status");
    queue.push(JobPriority::Poll, "value", {}, "value");
    const auto second = queue.push(JobPriority::Poll, "status 2", {}, "status");
    QCOMPARE(first.replaced, 0u);
    QCOMPARE(second.replaced, first.id);
    QVERIFY(second.id != first.id);
    QCOMPARE(queue.size(), 2);
    // The newer poll takes the older one's place.
    QCOMPARE(drain(queue), QStringList({"status 2", "value"}));
}

void TestJobQueue::pollKeysOnlyCollapseEqualKeys() {
    JobQueue queue;
    queue.push(JobPriority::Poll, "a", {}, "a");
    queue.push(JobPriority::Poll, "b", {}, "b");
    queue.push(JobPriority::Poll, "none", {});
    queue.push(JobPriority::Poll, "none again", {});
    QCOMPARE(queue.size(), 4);
}

void TestJobQueue::userJobsNeverCollapse() {
    JobQueue queue;
    queue.push(JobPriority::User, "u1", {}, "key");
    const auto second = queue.push(JobPriority::User, "u2", {}, "key");
    QCOMPARE(second.replaced, 0u);
    QCOMPARE(drain(queue), QStringList({"u1", "u2"}));
}

void TestJobQueue::cancelRemovesQueuedJob() {
    JobQueue queue;
    queue.push(JobPriority::User, "u1", {});
    const auto victim = queue.push(JobPriority::User, "u2", {});
    QCOMPARE(queue.cancel(victim.id), JobQueue::Cancelled::Removed);
    QCOMPARE(drain(queue), QStringList({"u1"}));
}

void TestJobQueue::cancelSignalsRunningJob() {
    JobQueue queue;
    const auto pushed = queue.push(JobPriority::User, "u1", {});
    const auto running = queue.takeNext();
    QVERIFY(running);
    QVERIFY(!running->cancel->load());
    QCOMPARE(queue.cancel(pushed.id), JobQueue::Cancelled::Signalled);
    QVERIFY(running->cancel->load());
    queue.finishRunning();
    QCOMPARE(queue.cancel(pushed.id), JobQueue::Cancelled::Unknown);
}

void TestJobQueue::cancelUnknownIdChangesNothing() {
    JobQueue queue;
    queue.push(JobPriority::User, "u1", {});
    QCOMPARE(queue.cancel(999), JobQueue::Cancelled::Unknown);
    QCOMPARE(queue.cancel(0), JobQueue::Cancelled::Unknown);
    QCOMPARE(queue.size(), 1);
}

void TestJobQueue::cancelAllEmptiesQueueAndSignalsRunningJob() {
    JobQueue queue;
    queue.push(JobPriority::User, "running", {});
    const auto running = queue.takeNext();
    const auto a = queue.push(JobPriority::User, "a", {});
    const auto b = queue.push(JobPriority::Poll, "b", {}, "b");
    const QList<quint64> removed = queue.cancelAll();
    QCOMPARE(removed, QList<quint64>({a.id, b.id}));
    QVERIFY(running->cancel->load());
    QCOMPARE(queue.size(), 0);
}

void TestJobQueue::urgentJobsComeFirst() {
    JobQueue queue;
    queue.push(JobPriority::Poll, "p1", {});
    queue.push(JobPriority::User, "u1", {});
    queue.push(JobPriority::Urgent, "stop", {});
    QCOMPARE(drain(queue), QStringList({"stop", "u1", "p1"}));
}

void TestJobQueue::urgentJobTakenWhileAnotherRunsLeavesItRunning() {
    JobQueue queue;
    const auto backup = queue.push(JobPriority::User, "backup", {});
    queue.push(JobPriority::User, "write", {});
    QCOMPARE(queue.takeNext()->title, QString("backup"));
    QVERIFY(!queue.takeUrgent(0).has_value());  // only urgent jobs come between
    queue.push(JobPriority::Urgent, "stop", {});
    QCOMPARE(queue.takeUrgent(0)->title, QString("stop"));
    // The backup is still the running job: cancel reaches it.
    QCOMPARE(queue.cancel(backup.id), JobQueue::Cancelled::Signalled);
}

void TestJobQueue::dropQueuedKeepsUrgentAndRunningJobs() {
    JobQueue queue;
    const auto backup = queue.push(JobPriority::User, "backup", {});
    QVERIFY(queue.takeNext().has_value());
    const auto move = queue.push(JobPriority::User, "move", {});
    const auto poll = queue.push(JobPriority::Poll, "poll", {}, "poll");
    queue.push(JobPriority::Urgent, "stop", {});
    QList<quint64> dropped;
    for (const QueuedJob& job : queue.dropQueued()) dropped << job.id;
    QCOMPARE(dropped, QList<quint64>({move.id, poll.id}));
    QCOMPARE(queue.size(), 1);
    QCOMPARE(queue.cancel(backup.id), JobQueue::Cancelled::Signalled);  // not touched
    queue.finishRunning();
    QCOMPARE(drain(queue), QStringList({"stop"}));
}

// Issue 35, item 3: motion never waits in a queue - refused, naming what
// holds the line, while a User or Urgent job runs or waits; a poll may run.
void TestJobQueue::motionIsPushedOnlyWhenTheLineIsFree() {
    JobQueue queue;
    queue.push(JobPriority::Poll, "poll", {}, "poll");
    QVERIFY(queue.takeNext());  // a poll runs: short, the motion goes next
    const JobQueue::PushedIfFree jog = queue.pushIfFree("jog", {}, {}, 0);
    QVERIFY(jog.pushed);
    queue.finishRunning();
    QCOMPARE(drain(queue), QStringList({"jog"}));

    queue.push(JobPriority::User, "Back up controller", {});
    QVERIFY(queue.takeNext());  // the backup runs
    const JobQueue::PushedIfFree refused = queue.pushIfFree("jog", {}, {}, 0);
    QVERIFY(!refused.pushed);
    QCOMPARE(refused.busyWith, QStringLiteral("Back up controller"));
    queue.push(JobPriority::User, "restore", {});
    queue.finishRunning();
    // Not running, but waiting: refused too, naming the waiting one.
    QCOMPARE(queue.pushIfFree("jog", {}, {}, 0).busyWith, QStringLiteral("restore"));
    QCOMPARE(drain(queue), QStringList({"restore"}));  // the jog was never queued
    queue.push(JobPriority::Urgent, "STOP", {});
    QCOMPARE(queue.pushIfFree("jog", {}, {}, 0).busyWith, QStringLiteral("STOP"));
}

void TestJobQueue::aJobRecordsTheStopGenerationItWasAskedIn() {
    JobQueue queue;
    queue.push(JobPriority::User, "move", {}, {}, {}, 3);
    QCOMPARE(queue.takeNext()->stopGeneration, 3u);
    queue.finishRunning();
    QVERIFY(queue.pushIfFree("jog", {}, {}, 4).pushed);
    QCOMPARE(queue.takeNext()->stopGeneration, 4u);
}

QTEST_GUILESS_MAIN(TestJobQueue)
#include "tst_job_queue.moc"
