// Issue 12, point 3: another device on the line is never shown or written as
// the old one. The GUI on the real QSerialPort against two simulated CamCons
// on pseudo-terminals with other contents; the simulators' state is the
// witness of what was written.
#include "pty_simulator.h"

#include "comm/sim/camcon/sim_demo.h"
#include "ui/camcon/cam_page.h"
#include "ui/camcon/cameditor/cam_document.h"
#include "ui/camcon/cameditor/cam_editor_widget.h"
#include "ui/camcon/device_writer.h"
#include "ui/connection_status.h"
#include "ui/device_session.h"
#include "ui/language.h"
#include "ui/report_dialog.h"

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
};

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

QTEST_MAIN(OtherDeviceTest)
#include "tst_other_device.moc"
