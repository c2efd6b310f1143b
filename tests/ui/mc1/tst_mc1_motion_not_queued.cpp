// Issue 35, item 3: motion never waits in a queue. A jog confirmed while an
// MC200 backup runs is refused at once with the reason on the page, and no
// jog telegram goes out when the backup ends. The backup is held in the
// middle of its variables deterministically (a request gate that waits on
// the worker thread), not by timing.
#include "../shell/shell_fixture.h"

#include "comm/engine/request_engine.h"
#include "ui/device_session.h"
#include "ui/mc1/mc1_axes_page.h"
#include "ui/mc1/mc1_window.h"

#include <QLabel>
#include <QPushButton>
#include <QSemaphore>
#include <QTemporaryDir>

#include <atomic>
#include <memory>

using namespace cambench;
using namespace cambench::test;

namespace {

// Installs `gate` on the connected device's engine (from a job, on the
// worker thread) and waits until it is in place.
bool setGate(DeviceSession* session, comm::RequestEngine::RequestGate gate) {
    bool done = false;
    QObject context;
    session->worker().run<bool>(
        &context, comm::JobPriority::User, QStringLiteral("gate"),
        [gate](comm::JobContext& job) {
            if (!job.device()) return false;
            job.device()->engine().setRequestGate(gate);
            return true;
        },
        [&done](bool) { done = true; });
    return QTest::qWaitFor([&done] { return done; }, kDeviceTimeoutMs);
}

// AXIS_DATA 9F, the telegram of moves and jogs (manual table 44).
bool isAxisData(const QByteArray& bytes) {
    return !bytes.isEmpty() && quint8(bytes.at(0)) == 0x9F;
}

}  // namespace

class Mc1MotionNotQueuedTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { useTestSettings(); }

    void aJogAskedDuringABackupIsRefusedAndNeverSent() {
        std::unique_ptr<Shell> shell =
            startOnSimulator(QStringLiteral("sim:variant=mc200v2"), QStringLiteral("mc1"));
        QVERIFY(shell);
        Mc1Window* mc1 = mc1Window(shell->window());
        Mc1AxesPage* axes = mc1->axesPage();
        shell->window()->showPage(axes);
        DeviceSession* session = shell->session();
        int jogTelegrams = 0;
        QObject counting;  // goes before jogTelegrams does
        connect(&session->worker(), &comm::JobRunner::traffic, &counting,
                [&jogTelegrams](const comm::TrafficEntry& entry) {
                    if (entry.outgoing && isAxisData(entry.bytes)) ++jogTelegrams;
                });
        // The backup reads variables with RDVAR: its tenth waits until the
        // jog has been asked.
        // Shared with the gate: it outlives this function if a check fails.
        auto inBackup = std::make_shared<QSemaphore>();
        auto goOn = std::make_shared<QSemaphore>();
        auto reads = std::make_shared<std::atomic_int>(0);
        QVERIFY(setGate(session, [inBackup, goOn, reads](const comm::Request& request) {
            if (request.label == QLatin1String("RDVAR") && ++*reads == 10) {
                inBackup->release();
                // Bounded: a failed check must not leave the worker waiting.
                (void)goOn->tryAcquire(1, kDeviceTimeoutMs);
            }
            return QString();
        }));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("backup.json"));
        mc1->backupToFile(path);
        QVERIFY(inBackup->tryAcquire(1, kDeviceTimeoutMs));

        {
            auto yes = answerConfirmation(true);
            axes->command(comm::Mc1AxisCommand::JogPlus);
            QCOMPARE(yes->answered(), 1);
        }
        const QLabel* result = axes->findChild<QLabel*>(QStringLiteral("pageResult"));
        // Refused at once: the backup is still held, and the page says why.
        QVERIFY(QTest::qWaitFor(
            [&] { return result->text().contains(QLatin1String("motion is not queued")); },
            kDeviceTimeoutMs));
        QVERIFY2(result->text().contains(QLatin1String("Back up controller")),
                 qPrintable(result->text()));

        goOn->release();
        QVERIFY(QTest::qWaitFor([&] { return QFile::exists(path); }, kDeviceTimeoutMs));
        QVERIFY(setGate(session, {}));  // every job before it has ended
        QTest::qWait(0);
        QCOMPARE(jogTelegrams, 0);
        QVERIFY(!axes->stateLabel()->text().contains(QLatin1String("moving")));

        // Asked again with the line free, the jog goes.
        auto yes = answerConfirmation(true);
        axes->command(comm::Mc1AxisCommand::JogPlus);
        QVERIFY(QTest::qWaitFor([&] { return jogTelegrams == 1; }, kDeviceTimeoutMs));
        axes->stopButton()->click();
    }
};

QTEST_MAIN(Mc1MotionNotQueuedTest)
#include "tst_mc1_motion_not_queued.moc"
