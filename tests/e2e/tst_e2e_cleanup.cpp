// Every program an end-to-end test starts ends with the test (issue 31,
// item 7): a test process that dies - aborted as QtTest's watchdog aborts
// it, or killed as CTest's TIMEOUT kills it - leaves no simulator running.
// A timed-out test once left its Cam-BUS simulator running, orphaned.
//
// The dying test is a second run of this executable with
// CAMBENCH_E2E_PID_FILE set: its functions start a real cambench-sim, write
// the simulator's process id to that file and die without cleaning up.
#include "e2e_support.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QFile>
#include <QProcess>
#include <QSaveFile>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <csignal>
#include <cstdlib>

using namespace cambench::e2e;

namespace {

const char* const kPidFileVariable = "CAMBENCH_E2E_PID_FILE";

bool isDyingTest() {
    return qEnvironmentVariableIsSet(kPidFileVariable);
}

// Written whole or not at all, so that the watching test never reads half.
bool writeSimulatorPid(qint64 pid) {
    QSaveFile file(qEnvironmentVariable(kPidFileVariable));
    return file.open(QIODevice::WriteOnly) && file.write(QByteArray::number(pid)) > 0 &&
           file.commit();
}

// Gone, or a zombie waiting for whoever adopted it to reap it: either way
// it runs no more.
bool processEnded(qint64 pid) {
    QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!stat.open(QIODevice::ReadOnly)) return true;
    const QByteArray line = stat.readAll();
    const qsizetype afterName = line.lastIndexOf(')');
    return afterName < 0 || line.mid(afterName + 2, 1) == "Z";
}

struct DyingTestRun {
    qint64 simulatorPid = 0;
    QString problem;
};

// Runs this executable's `function` as the dying test; with `kill`, kills
// it (SIGKILL) once its simulator runs.
DyingTestRun runDyingTest(const QString& function, bool kill) {
    // The dying test's orphans come to this process (not to init, which in
    // a container may never reap them), so that simulatorEnds() reaps them.
    prctl(PR_SET_CHILD_SUBREAPER, 1);
    DyingTestRun run;
    QTemporaryDir dir;
    const QString pidFile = dir.filePath(QStringLiteral("simulator.pid"));
    QProcess test;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QString::fromLatin1(kPidFileVariable), pidFile);
    test.setProcessEnvironment(environment);
    test.setProgram(QCoreApplication::applicationFilePath());
    test.setArguments({function});
    test.setStandardOutputFile(QProcess::nullDevice());
    test.setStandardErrorFile(QProcess::nullDevice());
    endWithThisTest(test);
    test.start();
    const QDeadlineTimer deadline(hangBoundMs(30000));
    while (!QFile::exists(pidFile) && !deadline.hasExpired() &&
           test.state() != QProcess::NotRunning)
        test.waitForFinished(20);
    QFile file(pidFile);
    if (file.open(QIODevice::ReadOnly)) run.simulatorPid = file.readAll().toLongLong();
    if (kill && test.state() != QProcess::NotRunning) ::kill(pid_t(test.processId()), SIGKILL);
    if (!test.waitForFinished(hangBoundMs(30000))) {
        test.kill();
        test.waitForFinished(hangBoundMs(5000));
        run.problem = QStringLiteral("the dying test did not end");
    } else if (run.simulatorPid <= 0) {
        run.problem = QStringLiteral("the dying test started no simulator");
    }
    return run;
}

// Bounded: the kernel's SIGKILL reaches the simulator at once, its end
// takes as long as the process needs to be torn down. The simulator is
// reaped (it is this process's orphan now); one that outlived its test is
// killed first, so that a failing run leaves nothing behind either.
bool simulatorEnds(qint64 pid) {
    const QDeadlineTimer deadline(hangBoundMs(10000));
    while (!processEnded(pid) && !deadline.hasExpired()) QThread::msleep(20);
    const bool ended = processEnded(pid);
    if (!ended) kill(pid_t(pid), SIGKILL);
    waitpid(pid_t(pid), nullptr, ended ? WNOHANG : 0);
    return ended;
}

}  // namespace

class TestE2eCleanup : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void simulatorEndsWhenTheTestAborts();
    void simulatorEndsWhenTheTestIsKilled();
    // The dying test's parts: skipped unless the two above run them.
    void abortWithASimulatorRunning();
    void waitWithASimulatorRunning();
};

void TestE2eCleanup::simulatorEndsWhenTheTestAborts() {
    if (isDyingTest()) QSKIP("this is the dying test");
    const DyingTestRun run = runDyingTest(QStringLiteral("abortWithASimulatorRunning"), false);
    QVERIFY2(run.problem.isEmpty(), qPrintable(run.problem));
    QVERIFY2(simulatorEnds(run.simulatorPid), "the simulator outlived its aborted test");
}

void TestE2eCleanup::simulatorEndsWhenTheTestIsKilled() {
    if (isDyingTest()) QSKIP("this is the dying test");
    const DyingTestRun run = runDyingTest(QStringLiteral("waitWithASimulatorRunning"), true);
    QVERIFY2(run.problem.isEmpty(), qPrintable(run.problem));
    QVERIFY2(simulatorEnds(run.simulatorPid), "the simulator outlived its killed test");
}

void TestE2eCleanup::abortWithASimulatorRunning() {
    if (!isDyingTest()) QSKIP("run by simulatorEndsWhenTheTestAborts");
    SimSession session;
    START_SIM(session);
    QVERIFY(writeSimulatorPid(session.simulatorPid()));
    // As QtTest's watchdog ends a test (qFatal): no destructor runs. No core
    // file for this intended abort.
    const rlimit noCore{0, 0};
    setrlimit(RLIMIT_CORE, &noCore);
    std::abort();
}

void TestE2eCleanup::waitWithASimulatorRunning() {
    if (!isDyingTest()) QSKIP("run by simulatorEndsWhenTheTestIsKilled");
    SimSession session;
    START_SIM(session);
    QVERIFY(writeSimulatorPid(session.simulatorPid()));
    // Until the watching test kills this process (bounded, should it not).
    QThread::msleep(hangBoundMs(60000));
    QFAIL("not killed");
}

QTEST_GUILESS_MAIN(TestE2eCleanup)
#include "tst_e2e_cleanup.moc"
