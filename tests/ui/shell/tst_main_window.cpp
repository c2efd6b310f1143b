// The shell's main window with a family that only the tests have (the fake
// family, tests/family/fake_family.h): the connection state it shows as
// the line comes, goes and reaches another device; the shell's log of it;
// the running job's title and progress in the status bar; closing without
// anything unwritten. Real widgets, the in-process simulator through the
// real worker, two fake devices that differ (2 and 3 axes). What the
// families' own pages do is tested in their folders (tests/ui/<family>/).
#include "fake_shell_fixture.h"

#include "ui/connection_page.h"
#include "ui/connection_status.h"
#include "ui/device_session.h"
#include "ui/language.h"

#include <QLabel>
#include <QLoggingCategory>
#include <QProgressBar>
#include <QSemaphore>
#include <QStatusBar>
#include <QtTest>

#include <optional>

using namespace cambench;
using namespace cambench::test;

namespace {

const QString kTwoAxes = QStringLiteral("sim:throttle=0,axes=2");
const QString kThreeAxes = QStringLiteral("sim:throttle=0,axes=3");
const QString kFakeLine = QStringLiteral("fake-line");

// Connects as a person does on the connection page and waits for the load.
bool connectThroughThePage(MainWindow* window, const QString& port) {
    window->connectionPage()->setPort(port);
    window->connectionPage()->setProtocol(kFakeLine);
    QSignalSpy loaded(window, &MainWindow::loaded);
    window->connectAndLoad();
    return loaded.wait(kDeviceTimeoutMs) && loaded.first().first().toBool();
}

// The status bar's label that holds `text`, or nullptr.
QLabel* statusLabel(MainWindow* window, const QString& text) {
    for (QLabel* label : window->statusBar()->findChildren<QLabel*>())
        if (label->text() == text) return label;
    return nullptr;
}

// What the shell's category ("cambench.ui") logs while it is captured.
QStringList g_shellLog;
void captureShellLog(QtMsgType, const QMessageLogContext& context, const QString& text) {
    if (QLatin1String(context.category) == QLatin1String("cambench.ui")) g_shellLog << text;
}

}  // namespace

class MainWindowTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { QVERIFY(setUpWithTheFakeFamily()); }
    void connectionStateFollowsTheLineAndTheDevice();
    void theShellLogsEachConnectionStateWithItsReason();
    void statusBarShowsTheRunningJobAndItsProgress();
    void closingAsksNothingWhenNothingIsUnwritten();
};

// Connected, the strip names the device; a port that is not there leaves
// nothing of it and says why; another device reached through the
// connection page is named as itself.
void MainWindowTest::connectionStateFollowsTheLineAndTheDevice() {
    auto shell = startOnFake(kTwoAxes);
    QVERIFY(shell);
    MainWindow* window = shell->window();
    DeviceSession* session = shell->session();
    QVERIFY(session->isOnline());
    QCOMPARE(window->connectionPage()->family(), QStringLiteral("fake"));
    ConnectionStrip* strip = window->connectionStrip();
    QVERIFY2(strip->text().contains(QLatin1String("FAKE-1 simulated axes=2")),
             qPrintable(strip->text()));
    QVERIFY(!strip->isAlarm());

    comm::ConnectionSettings gone;
    gone.port = QStringLiteral("/dev/cambench-no-such-port");
    session->connectTo(gone, session->protocolSettings());
    QTRY_VERIFY_WITH_TIMEOUT(session->state() == comm::ConnectionState::Disconnected,
                             kDeviceTimeoutMs);
    QVERIFY(!session->isOnline());
    QVERIFY2(!strip->text().contains(QLatin1String("FAKE-1")), qPrintable(strip->text()));
    QVERIFY2(window->lastMessage().startsWith(QLatin1String("Not connected:")),
             qPrintable(window->lastMessage()));

    QVERIFY(connectThroughThePage(window, kThreeAxes));
    QVERIFY(session->isOnline());
    QVERIFY2(strip->text().contains(QLatin1String("FAKE-1 simulated axes=3")),
             qPrintable(strip->text()));
    QVERIFY2(!strip->text().contains(QLatin1String("axes=2")), qPrintable(strip->text()));
}

// The shell's category says each state the line goes through, with the
// reason of a failed connect (for a log a person sends along).
void MainWindowTest::theShellLogsEachConnectionStateWithItsReason() {
    auto shell = startOnFake(kTwoAxes);
    QVERIFY(shell);
    DeviceSession* session = shell->session();
    g_shellLog.clear();
    QLoggingCategory::setFilterRules(QStringLiteral("cambench.ui.info=true"));
    const QtMessageHandler before = qInstallMessageHandler(captureShellLog);
    comm::ConnectionSettings gone;
    gone.port = QStringLiteral("/dev/cambench-no-such-port");
    session->connectTo(gone, session->protocolSettings());
    const bool disconnected = QTest::qWaitFor(
        [session] { return session->state() == comm::ConnectionState::Disconnected; },
        kDeviceTimeoutMs);
    qInstallMessageHandler(before);
    QLoggingCategory::setFilterRules(QString());
    QVERIFY(disconnected);
    const QStringList states = g_shellLog.filter(QStringLiteral("connection state"));
    QVERIFY2(states.size() >= 2, qPrintable(g_shellLog.join(QLatin1Char('\n'))));
    QVERIFY2(states.last().contains(QLatin1String("cambench-no-such-port")),
             qPrintable(states.last()));
}

// A job's title and bar show while it runs (its progress as it reports
// it) and go when it is done.
void MainWindowTest::statusBarShowsTheRunningJobAndItsProgress() {
    auto shell = startOnFake(kTwoAxes);
    QVERIFY(shell);
    MainWindow* window = shell->window();
    auto* bar = window->statusBar()->findChild<QProgressBar*>();
    QVERIFY(bar);
    QVERIFY(bar->isHidden());
    QSemaphore halfway;
    QSemaphore release;
    std::optional<bool> done;
    QObject context;
    shell->session()->worker().run<bool>(
        &context, comm::JobPriority::User, QStringLiteral("Counting the fake axes"),
        [&halfway, &release](comm::JobContext& job) {
            job.progress(1, 2);
            halfway.release();
            return release.tryAcquire(1, kDeviceTimeoutMs);
        },
        [&done](bool released) { done = released; });
    QVERIFY(halfway.tryAcquire(1, kDeviceTimeoutMs));
    QTRY_VERIFY_WITH_TIMEOUT(statusLabel(window, QStringLiteral("Counting the fake axes")),
                             kDeviceTimeoutMs);
    QVERIFY(!bar->isHidden());
    QTRY_COMPARE_WITH_TIMEOUT(bar->value(), 500, kDeviceTimeoutMs);
    QCOMPARE(bar->maximum(), 1000);

    release.release();
    QTRY_VERIFY_WITH_TIMEOUT(done.has_value(), kDeviceTimeoutMs);
    QVERIFY(*done);
    QTRY_VERIFY_WITH_TIMEOUT(bar->isHidden(), kDeviceTimeoutMs);
    QVERIFY(!statusLabel(window, QStringLiteral("Counting the fake axes")));
}

// A family without edits leaves nothing unwritten: the title counts none
// and closing asks nothing.
void MainWindowTest::closingAsksNothingWhenNothingIsUnwritten() {
    auto shell = startOnFake(kTwoAxes);
    QVERIFY(shell);
    MainWindow* window = shell->window();
    QVERIFY2(!window->windowTitle().contains(QLatin1String("not written")),
             qPrintable(window->windowTitle()));
    QVERIFY(!window->isWindowModified());
    // Any question would be a modal dialog: it would be answered No here,
    // and counted.
    NextDialog<QDialog> question([](QDialog* dialog) { dialog->reject(); });
    QVERIFY(window->confirmClose());
    QCOMPARE(question.answered(), 0);
}

QTEST_MAIN(MainWindowTest)
#include "tst_main_window.moc"
