// Issue 30, item 1: runDevicesByPort (app/cli/machine_parallel.h) without
// devices. Two devices on different ports meet (each waits for the other
// to have started: only possible when they run at once); the devices of one
// port never overlap and keep the file's order, whatever name the port is
// given (a path and a link to it are one port); each device's `done` runs
// once, on the calling thread.
#include "app/cli/machine_parallel.h"

#include <QFile>
#include <QSemaphore>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

#include <algorithm>
#include <atomic>
#include <mutex>

using namespace cambench::cli;

namespace {

GlobalOptions onPort(const QString& port) {
    GlobalOptions options;
    options.port = port;
    return options;
}

// A bound for a wait that is instant unless the code under test is wrong
// (then the wait fails instead of hanging): not a performance limit.
constexpr int kHangBoundMs = 60000;

}  // namespace

class TestCliMachineParallel : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void differentPortsAtOnceOnePortInOrder() {
        QTemporaryDir dir;
        const QString port = dir.filePath(QStringLiteral("ttyA"));
        QVERIFY(QFile(port).open(QIODevice::WriteOnly));
        const QString link = dir.filePath(QStringLiteral("ttyA-link"));
        QVERIFY(QFile::link(port, link));
        // 0 and 2 share a port (by its path and by a link), 1 has its own.
        const QList<GlobalOptions> options{onPort(port), onPort(QStringLiteral("tcp://ds:4001")),
                                           onPort(link)};

        QSemaphore firstStarted;
        QSemaphore otherStarted;
        bool met[2] = {false, false};
        std::atomic<int> onPortA{0};
        std::atomic<int> mostOnPortA{0};
        std::mutex orderLock;
        QList<int> portAOrder;
        const auto work = [&](int i) {
            if (i == 1) {
                otherStarted.release();
                met[1] = firstStarted.tryAcquire(1, kHangBoundMs);
                return;
            }
            const int now = ++onPortA;
            int most = mostOnPortA;
            while (now > most && !mostOnPortA.compare_exchange_weak(most, now)) {
            }
            if (i == 0) {
                firstStarted.release();
                met[0] = otherStarted.tryAcquire(1, kHangBoundMs);
            }
            {
                const std::lock_guard<std::mutex> lock(orderLock);
                portAOrder << i;
            }
            --onPortA;
        };
        QList<int> done;
        QList<bool> doneOnCaller;
        runDevicesByPort(options, {0, 1, 2}, work, [&](int i) {
            done << i;
            doneOnCaller << (QThread::currentThread() == thread());
        });

        QVERIFY2(met[0] && met[1], "the devices on two ports did not run at once");
        QCOMPARE(mostOnPortA.load(), 1);
        QCOMPARE(portAOrder, (QList<int>{0, 2}));
        std::sort(done.begin(), done.end());
        QCOMPARE(done, (QList<int>{0, 1, 2}));
        QCOMPARE(doneOnCaller, (QList<bool>{true, true, true}));
    }

    // Only the devices asked for run (restore --only), and none at all is fine.
    void onlyTheIndicesGiven() {
        const QList<GlobalOptions> options{onPort(QStringLiteral("/dev/cambench-a")),
                                           onPort(QStringLiteral("/dev/cambench-b")),
                                           onPort(QStringLiteral("/dev/cambench-c"))};
        std::mutex lock;
        QList<int> ran;
        runDevicesByPort(options, {2}, [&](int i) {
            const std::lock_guard<std::mutex> guard(lock);
            ran << i;
        });
        QCOMPARE(ran, QList<int>{2});
        runDevicesByPort(options, {}, [&](int i) { ran << i; });
        QCOMPARE(ran, QList<int>{2});
    }
};

QTEST_GUILESS_MAIN(TestCliMachineParallel)
#include "tst_cli_machine_parallel.moc"
