// Issue 12, point 3: another device on the line is never shown or written as
// the old one. The GUI on the real QSerialPort against two simulated CamCons
// on pseudo-terminals with other contents; the simulators' state is the
// witness of what was written.
#include "pty_simulator.h"

#include "comm/sim/camcon/sim_demo.h"
#include "comm/sim/sim_tcp_server.h"
#include "ui/camcon/cam_page.h"
#include "ui/camcon/cameditor/cam_document.h"
#include "ui/camcon/cameditor/cam_editor_widget.h"
#include "ui/camcon/device_change_dialog.h"
#include "ui/camcon/device_writer.h"
#include "ui/connection_status.h"
#include "ui/device_session.h"
#include "ui/language.h"
#include "ui/report_dialog.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace cambench;
using namespace cambench::test;

namespace {

void connectToPort(Shell& shell, const QString& port) {
    comm::ConnectionSettings connection = shell.session()->connection();
    connection.port = port;
    shell.session()->connectTo(connection, shell.session()->protocolSettings());
}

QString stripText(Shell& shell) {
    auto* strip = shell.window()->findChild<ConnectionStrip*>();
    return strip ? strip->text() : QString();
}

std::optional<WriteResult> writeProgram(Shell& shell, int program) {
    std::optional<WriteResult> result;
    const auto reports =
        std::make_unique<NextDialog<ReportDialog>>([](ReportDialog* dialog) { dialog->accept(); });
    camConWindow(shell.window())->camPage()->writeProgram(program, [&](const WriteResult& r) {
        result = r;
    });
    (void)QTest::qWaitFor([&result] { return result.has_value(); }, kDeviceTimeoutMs);
    return result;
}

}  // namespace

class OtherDeviceTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        useTestSettings();
        QVERIFY(setLanguage(QStringLiteral("en")));
    }
    void anotherPortShowsTheNewDeviceAndWritesOnlyWhatItHolds();
    void aDeviceChangedBehindThePcIsNotWrittenFromTheOldCopy();
    void theSameDeviceAgainKeepsItsCopies();
    void readProgramRefreshesNamesAndDeadTimes();
    // Issue 28, point 1: an edit is what the person changed, nothing else.
    void theNewDevicesValuesAreTheDefault();
    void keptChangesAreOnlyWhatThePersonChanged();
    void aCopyOfTheOldDeviceIsWrittenAsACopy();
    void aMultiuserNumberChangeCarriesOnlyTheChanges();
    void aDeviceServerWithAnotherCamConBehindIt();
    // Issue 28, point 3.
    void reEstablishedOnlyOnceTheDeviceIdentifiedItself();
};

namespace {

// Device A (the demo) read, one cam of program 0 output 1 changed, then
// device B (two cams on every track) on another port: the question is
// answered with `carry`. Returns the dialog's list of changes.
struct DeviceChange {
    QString changes;
    int replaceQuestions = 0;
    QList<Cam> mine;  // program 0, output 1 as the person changed it
};
DeviceChange changeDevice(Shell& shell, const std::function<void()>& toOther,
                          std::optional<CarryOver> carry) {
    CamDocument* cams = camConWorkspace(shell)->cams();
    cams->setCam(0, 1, 0, {25, 60});
    DeviceChange change;
    change.mine = cams->track(0, 1).cams;
    NextDialog<DeviceChangeDialog> question([&](DeviceChangeDialog* dialog) {
        change.changes = dialog->changesText();
        if (carry) dialog->choose(*carry);
        dialog->accept();
    });
    const auto replace = answerReplaceEdits(false);
    toOther();
    (void)QTest::qWaitFor(
        [&] {
            return shell.session()->deviceChecked() &&
                   camConWorkspace(shell)->readTimes().programs.contains(0) &&
                   camConWorkspace(shell)->readTimes().parts.contains(ProjectPart::OutputNames);
        },
        kDeviceTimeoutMs);
    change.replaceQuestions = replace->answered();
    if (question.answered() != 1) change.changes = QStringLiteral("<not asked>");
    return change;
}

// Device A (the demo) with the GUI on it, and device B (two cams on every
// track) on another pseudo-terminal.
struct TwoDevices {
    PtySimulator a;
    PtySimulator b;
    std::unique_ptr<Shell> shell;
    TwoDevices() {
        comm::fillBenchmarkCams(b.device(), 2);
        shell = startOnPty(a);
    }
    DeviceChange toB(std::optional<CarryOver> carry) {
        return changeDevice(
            *shell, [this] { connectToPort(*shell, b.path()); }, carry);
    }
};

}  // namespace

void OtherDeviceTest::theNewDevicesValuesAreTheDefault() {
    TwoDevices devices;
    QVERIFY(devices.shell);
    const DeviceChange change = devices.toB(std::nullopt);
    QVERIFY2(change.changes.startsWith(QStringLiteral("Program 0, output 1: 25–60")),
             qPrintable(change.changes));
    QCOMPARE(change.changes.count(QLatin1Char('\n')), 0);  // one change, one line
    CamDocument* cams = camConWorkspace(*devices.shell)->cams();
    QCOMPARE(cams->track(0, 1).cams, devices.b.track(0, 1));
    QCOMPARE(cams->track(0, 3).cams, devices.b.track(0, 3));
    QCOMPARE(camConWorkspace(*devices.shell)->changedCount(), 0);
    QVERIFY(!camConWorkspace(*devices.shell)->carriedFrom());
}

void OtherDeviceTest::keptChangesAreOnlyWhatThePersonChanged() {
    TwoDevices devices;
    QVERIFY(devices.shell);
    const DeviceChange change = devices.toB(CarryOver::Changes);
    QCOMPARE(change.replaceQuestions, 0);  // decided once, not asked again per read
    QVERIFY2(!change.changes.contains(QStringLiteral("output 2")), qPrintable(change.changes));
    Workspace* workspace = camConWorkspace(*devices.shell);
    CamDocument* cams = workspace->cams();
    // The change, applied to B's values; every other item is B's.
    QCOMPARE(cams->track(0, 1).cams, change.mine);
    QCOMPARE(cams->trackState(0, 1), ChangeState::Edited);
    for (int output = 2; output <= workspace->info().outputs; ++output) {
        QCOMPARE(cams->track(0, output).cams, devices.b.track(0, output));
        QCOMPARE(cams->trackState(0, output), ChangeState::Unchanged);
    }
    QCOMPARE(cams->programName(0), cams->deviceProgram(0)->name);
    QCOMPARE(workspace->changedCount(), 1);
    // The banner's text (the strip shows it while the line answers).
    QVERIFY2(workspace->otherDeviceNote().contains(QStringLiteral("Your changes (1) stay")),
             qPrintable(workspace->otherDeviceNote()));
    // A program never read from B holds nothing of A's.
    QVERIFY(cams->track(1, 1).cams.isEmpty() || cams->track(1, 1).cams == devices.b.track(1, 1));
}

void OtherDeviceTest::aCopyOfTheOldDeviceIsWrittenAsACopy() {
    TwoDevices devices;
    QVERIFY(devices.shell);
    const QList<Cam> demoOutput3 = devices.a.track(0, 3);
    QVERIFY(demoOutput3 != devices.b.track(0, 3));
    const DeviceChange change = devices.toB(CarryOver::Everything);
    QCOMPARE(change.replaceQuestions, 0);
    Workspace* workspace = camConWorkspace(*devices.shell);
    QVERIFY(workspace->carriedFrom().has_value());
    QCOMPARE(workspace->carriedFrom()->carry, CarryOver::Everything);
    CamDocument* cams = workspace->cams();
    QCOMPARE(cams->track(0, 3).cams, demoOutput3);
    QCOMPARE(cams->trackState(0, 3), ChangeState::Edited);
    // The old device named once: the banner fits whole.
    QVERIFY2(workspace->otherDeviceNote().contains(
                 QStringLiteral("A copy of that device's values waits to be written.")),
             qPrintable(workspace->otherDeviceNote()));
    QCOMPARE(workspace->otherDeviceNote().count(QLatin1String("CamCon")), 1);
    const std::optional<WriteResult> result = writeProgram(*devices.shell, 0);
    QVERIFY(result.has_value());
    QVERIFY2(result->ok(), qPrintable(writeSummary(*result)));
    QCOMPARE(devices.b.track(0, 3), demoOutput3);
    QCOMPARE(devices.b.track(0, 1), change.mine);
}

void OtherDeviceTest::anotherPortShowsTheNewDeviceAndWritesOnlyWhatItHolds() {
    PtySimulator demo;
    auto shell = startOnPty(demo);
    QVERIFY(shell);
    Workspace* workspace = camConWorkspace(*shell);
    CamDocument* cams = workspace->cams();
    const qint32 demoCams = workspace->info().programmedCams;
    QCOMPARE(cams->trackState(0, 1), ChangeState::Unchanged);

    // Another CamCon with two cams on every output of every program.
    PtySimulator other;
    QVERIFY(other.isOpen());
    comm::fillBenchmarkCams(other.device(), 2);
    const QList<Cam> otherOutput5 = other.track(0, 5);
    QCOMPARE(otherOutput5.size(), 2);
    connectToPort(*shell, other.path());
    QTRY_VERIFY_WITH_TIMEOUT(shell->session()->isOnline() && shell->session()->deviceChecked(),
                             kDeviceTimeoutMs);
    // The panel, title and banner follow the device on the line.
    QTRY_VERIFY_WITH_TIMEOUT(workspace->info().programmedCams != demoCams, kDeviceTimeoutMs);
    QTRY_VERIFY2_WITH_TIMEOUT(stripText(*shell).contains(QStringLiteral("Another device answers")),
                              qPrintable(stripText(*shell)), kDeviceTimeoutMs);
    // What the page shows as on the device is read from the new device.
    QTRY_VERIFY_WITH_TIMEOUT(cams->deviceTrack(0, 5).has_value(), kDeviceTimeoutMs);
    QCOMPARE(cams->deviceTrack(0, 5)->cams, otherOutput5);
    QCOMPARE(cams->track(0, 5).cams, otherOutput5);
    QCOMPARE(cams->track(0, 1).cams, other.track(0, 1));
    QVERIFY(!cams->hasDeviceCopy(1));  // never read from this device

    // One cam added on output 5: only output 5 changes on the device.
    QList<QList<Cam>> before;
    for (int output = 1; output <= workspace->info().outputs; ++output)
        before << other.track(0, output);
    Track wanted = cams->track(0, 5);
    wanted.cams << Cam{350, 355};
    cams->replaceTrack(0, wanted, QStringLiteral("test edit"));
    other.injections().clearLog();
    const std::optional<WriteResult> result = writeProgram(*shell, 0);
    QVERIFY(result.has_value());
    QVERIFY2(result->ok(), qPrintable(writeSummary(*result)));
    QCOMPARE(result->value().count(usecases::WriteState::Written), 1);
    QCOMPARE(other.track(0, 5), wanted.cams);
    for (int output = 1; output <= workspace->info().outputs; ++output) {
        if (output != 5) QCOMPARE(other.track(0, output), before.at(output - 1));
    }
    // Nothing reached the old device.
    QVERIFY(demo.track(0, 5) != wanted.cams);
}

void OtherDeviceTest::aDeviceChangedBehindThePcIsNotWrittenFromTheOldCopy() {
    PtySimulator sim;
    auto shell = startOnPty(sim);
    QVERIFY(shell);
    CamDocument* cams = camConWorkspace(*shell)->cams();
    // Someone reprograms the device at its panel (or another device takes
    // its place on a device server): the copy is no longer what it holds.
    comm::fillBenchmarkCams(sim.device(), 3);
    Track wanted = cams->track(0, 2);
    wanted.cams = {{100, 120}};
    cams->replaceTrack(0, wanted, QStringLiteral("test edit"));
    sim.injections().clearLog();
    const std::optional<WriteResult> result = writeProgram(*shell, 0);
    QVERIFY(result.has_value());
    QVERIFY(!result->ok());
    QVERIFY2(result->error().message.contains(QStringLiteral("Nothing was written")),
             qPrintable(result->error().message));
    QCOMPARE(sim.commandsReceived(), 0);
    QCOMPARE(cams->track(0, 2).cams, wanted.cams);  // the edit stays
}

void OtherDeviceTest::theSameDeviceAgainKeepsItsCopies() {
    PtySimulator sim;
    auto shell = startOnPty(sim);
    QVERIFY(shell);
    CamDocument* cams = camConWorkspace(*shell)->cams();
    cams->setCam(0, 1, 0, {12, 90});
    shell->session()->reconnect();
    QTRY_VERIFY_WITH_TIMEOUT(shell->session()->isOnline() && shell->session()->deviceChecked(),
                             kDeviceTimeoutMs);
    QVERIFY(cams->hasDeviceCopy(0));
    QCOMPARE(cams->trackState(0, 1), ChangeState::Edited);
    QCOMPARE(cams->trackState(0, 2), ChangeState::Unchanged);
    QVERIFY(camConWorkspace(*shell)->otherDeviceNote().isEmpty());
}

void OtherDeviceTest::readProgramRefreshesNamesAndDeadTimes() {
    // Issue 12, point 3: the cam page's Name and Dead time columns stayed
    // as first read while Read Program refreshed only the cams.
    PtySimulator sim;
    auto shell = startOnPty(sim);
    QVERIFY(shell);
    Workspace* workspace = camConWorkspace(*shell);
    QTRY_VERIFY_WITH_TIMEOUT(workspace->outputSettingsKnown(), kDeviceTimeoutMs);
    sim.device().state().deadTimes.insert(1, 35);  // output 2: 3.5 ms, set at the panel
    sim.device().state().outputNames.insert(1, QByteArray("Glue"));
    camConWindow(shell->window())->camPage()->editor()->editorActions().at(0)->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(workspace->cams()->deadTime(2), 35, kDeviceTimeoutMs);
    QTRY_COMPARE_WITH_TIMEOUT(workspace->cams()->outputName(2), QStringLiteral("Glue"),
                              kDeviceTimeoutMs);
    QCOMPARE(workspace->deviceDeadTime(2), 35);
}

void OtherDeviceTest::aMultiuserNumberChangeCarriesOnlyTheChanges() {
    PtySimulator line(false, 38400, {0, 5});
    QVERIFY(line.isOpen());
    comm::fillBenchmarkCams(line.device(5), 2);
    auto shell = startOnSimulator(line.path(), QStringLiteral("multiuser"));
    QVERIFY(shell);
    const DeviceChange change = changeDevice(
        *shell, [&] { shell->session()->setDevice(5); }, CarryOver::Changes);
    QCOMPARE(change.replaceQuestions, 0);
    QVERIFY2(change.changes.startsWith(QStringLiteral("Program 0, output 1: ")),
             qPrintable(change.changes));
    QCOMPARE(change.changes.count(QLatin1Char('\n')), 0);
    CamDocument* cams = camConWorkspace(*shell)->cams();
    QCOMPARE(cams->track(0, 1).cams, change.mine);
    QCOMPARE(cams->track(0, 2).cams, line.track(0, 2, 5));
    QCOMPARE(camConWorkspace(*shell)->changedCount(), 1);
    QCOMPARE(camConWorkspace(*shell)->info().deviceNumber, 5);
}

void OtherDeviceTest::aDeviceServerWithAnotherCamConBehindIt() {
    // The same TCP address (a serial device server) before and after: the
    // CamCon behind it was replaced by one with another firmware, 16 outputs
    // and other cams. The line drops, the GUI reconnects to the address by
    // itself, and the new device's values are the default.
    comm::SimPortConfig config;
    config.throttle = false;
    comm::SimPacer pacer(config.baud, false);
    std::unique_ptr<comm::SimLine> lineA = comm::makeSimLine(config);
    auto serverA = std::make_unique<comm::SimTcpServer>(*lineA, pacer);
    QVERIFY(serverA->listen(0).ok());
    const quint16 port = serverA->port();
    const QString address = QStringLiteral("tcp://127.0.0.1:%1").arg(port);
    auto shell = startOnSimulator(address);
    QVERIFY(shell);
    DeviceSession* session = shell->session();
    session->setRetryInterval(100);
    QVERIFY(waitForSections(*shell));
    QCOMPARE(camConWorkspace(*shell)->info().outputs, 32);

    comm::SimProfile replacement;
    replacement.epromDate = "03.05.2001";
    replacement.outputs = 16;
    std::unique_ptr<comm::SimLine> lineB = comm::makeSimLine(config, replacement);
    comm::fillBenchmarkCams(*lineB->device(0), 2);
    std::unique_ptr<comm::SimTcpServer> serverB;
    bool listening = false;
    const DeviceChange change = changeDevice(
        *shell,
        [&] {
            serverA.reset();  // the device server drops the connection
            (void)QTest::qWaitFor([session] { return session->isRetrying(); }, kDeviceTimeoutMs);
            serverB = std::make_unique<comm::SimTcpServer>(*lineB, pacer);
            listening = serverB->listen(port).ok();
        },
        std::nullopt);
    QVERIFY2(listening, "port taken again by the second device server");
    QTRY_COMPARE_WITH_TIMEOUT(camConWorkspace(*shell)->info().outputs, 16, kDeviceTimeoutMs);
    QVERIFY2(change.changes.startsWith(QStringLiteral("Program 0, output 1: 25–60")),
             qPrintable(change.changes));
    QCOMPARE(change.changes.count(QLatin1Char('\n')), 0);
    CamDocument* cams = camConWorkspace(*shell)->cams();
    QTRY_COMPARE_WITH_TIMEOUT(cams->track(0, 1).cams, lineB->device(0)->state().cams.track(0, 0),
                              kDeviceTimeoutMs);
    QCOMPARE(cams->track(0, 16).cams, lineB->device(0)->state().cams.track(0, 15));
    QCOMPARE(camConWorkspace(*shell)->changedCount(), 0);
    QCOMPARE(session->connection().port, address);
    QTRY_VERIFY2_WITH_TIMEOUT(stripText(*shell).contains(QStringLiteral("Another device answers")),
                              qPrintable(stripText(*shell)), kDeviceTimeoutMs);
    QVERIFY2(stripText(*shell).contains(QStringLiteral("03.05.2001")),
             qPrintable(stripText(*shell)));
}

void OtherDeviceTest::reEstablishedOnlyOnceTheDeviceIdentifiedItself() {
    // The port is a name (a symlink, as udev's by-id names are): the device
    // behind it goes, and another program's device appears under the name.
    QTemporaryDir dir;
    const QString port = dir.filePath(QStringLiteral("ttyPLANT"));
    auto a = std::make_unique<PtySimulator>();
    QVERIFY(QFile::link(a->path(), port));
    auto shell = startOnSimulator(port);
    QVERIFY(shell);
    DeviceSession* session = shell->session();
    session->setRetryInterval(100);
    QSignalSpy reconnected(session, &DeviceSession::reconnected);
    QSignalSpy reestablished(session, &DeviceSession::reestablished);
    int reestablishedAtReconnect = -1;
    connect(session, &DeviceSession::reconnected, this,
            [&] { reestablishedAtReconnect = int(reestablished.size()); });
    a->stop();
    QTRY_VERIFY_WITH_TIMEOUT(session->isRetrying(), kDeviceTimeoutMs);
    PtySimulator b;
    comm::fillBenchmarkCams(b.device(), 2);
    QVERIFY(QFile::remove(port));
    QVERIFY(QFile::link(b.path(), port));
    QTRY_VERIFY_WITH_TIMEOUT(reestablished.size() == 1, kDeviceTimeoutMs);
    QCOMPARE(reconnected.size(), 1);
    QCOMPARE(reestablishedAtReconnect, 0);  // not said on the bare line
    QVERIFY(session->deviceChecked());
    QCOMPARE(reestablished.first().first().toBool(), false);  // another device, said so
    QTRY_VERIFY2_WITH_TIMEOUT(stripText(*shell).contains(QStringLiteral("Another device answers")),
                              qPrintable(stripText(*shell)), kDeviceTimeoutMs);
}

QTEST_MAIN(OtherDeviceTest)
#include "tst_other_device.moc"
