// The CamCon's cam programs in the window against the in-process simulator
// through the real CommWorker: read at the start, edited, written and read
// back; the timing at a speed; a read on a dead line keeps the edits; the
// unwritten edits counted in the title before closing.
#include "camcon_fixture.h"

#include "comm/camcon/ascii/ascii_protocol.h"
#include "ui/camcon/cam_page.h"
#include "ui/camcon/cameditor/cam_diagram_widget.h"
#include "ui/camcon/cameditor/cam_editor_widget.h"
#include "ui/camcon/timing_bar.h"
#include "ui/device_session.h"
#include "ui/language.h"

#include <QMessageBox>
#include <QTimer>
#include <QtTest>

using namespace cambench;
using namespace cambench::test;

class CamPageTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    // As the application does at start: English catalogue (plural forms).
    void initTestCase() {
        useTestSettings();
        QVERIFY(setLanguage(QStringLiteral("en")));
    }
    void startReadsIdentityAndProgramZero_data() { protocolRows(); }
    void startReadsIdentityAndProgramZero();
    void editedCamWrittenAndReadBackEqualsEdit_data() { protocolRows(); }
    void editedCamWrittenAndReadBackEqualsEdit();
    void timingAtSpeedIsDrawnUnderTheCamsAndWarns();
    void failedReadOnDeadLineKeepsEditsAndSaysWhy();
    void closingWithUnwrittenChangesCountsThem();
};

void CamPageTest::startReadsIdentityAndProgramZero() {
    QFETCH(QString, protocol);
    auto shell = startOnSimulator(QStringLiteral("sim:throttle=0"), protocol);
    QVERIFY(shell);
    QVERIFY(camConWorkspace(*shell)->infoFromDevice());
    QCOMPARE(camConWorkspace(*shell)->info().epromDate, QStringLiteral("11.10.1994"));
    QVERIFY(camConWorkspace(*shell)->cams()->hasDeviceCopy(0));
    QVERIFY(!camConWorkspace(*shell)->cams()->program(0).tracks.isEmpty());
    QCOMPARE(camConWorkspace(*shell)->changedCount(), 0);
}

void CamPageTest::editedCamWrittenAndReadBackEqualsEdit() {
    QFETCH(QString, protocol);
    auto shell = startOnSimulator(QStringLiteral("sim:throttle=0"), protocol);
    QVERIFY(shell);
    CamDocument* cams = camConWorkspace(*shell)->cams();
    const Track before = cams->track(0, 1);
    QVERIFY(!before.cams.isEmpty());
    Cam edited = before.cams.first();
    edited.off += 7;
    cams->setCam(0, 1, 0, edited);
    QCOMPARE(cams->trackState(0, 1), ChangeState::Edited);

    CamPage* page = camConWindow(shell->window())->camPage();
    std::optional<WriteResult> result;
    page->writeProgram(0, [&](const WriteResult& r) { result = r; });
    QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), kDeviceTimeoutMs);
    QVERIFY2(result->ok() && result->value().complete(), qPrintable(writeSummary(*result)));
    QCOMPARE(result->value().count(usecases::WriteState::Written), 1);
    QCOMPARE(cams->trackState(0, 1), ChangeState::Unchanged);

    // Make the PC copy differ, then read and take the device's: it must
    // hold the edit.
    cams->setCam(0, 1, 0, before.cams.first());
    const auto answer = answerReplaceEdits(false);
    std::optional<Status> read;
    page->readProgram(0, [&](const Status& s) { read = s; });
    QTRY_VERIFY_WITH_TIMEOUT(read.has_value(), kDeviceTimeoutMs);
    QVERIFY(read->ok());
    QCOMPARE(answer->answered(), 1);
    QCOMPARE(cams->track(0, 1).cams.first(), edited);
    QCOMPARE(cams->changedCount(), 0);
}

void CamPageTest::timingAtSpeedIsDrawnUnderTheCamsAndWarns() {
    auto shell = startOnSimulator(QStringLiteral("sim:throttle=0"));
    QVERIFY(shell);
    CamPage* page = camConWindow(shell->window())->camPage();
    CamDocument* cams = camConWorkspace(*shell)->cams();
    TimingBar* bar = page->timingBar();
    CamDiagramWidget* diagram = page->editor()->diagram();
    page->editor()->setCurrentProgram(0);
    QVERIFY(!diagram->timingShown());
    QVERIFY(!cams->track(0, 1).cams.isEmpty());
    cams->setDeadTime(1, 100);  // 10 ms
    bar->setSpeed(60);
    bar->setTimingShown(true);
    QVERIFY(diagram->timingShown());
    QVERIFY(!bar->timing().isEmpty());
    QCOMPARE(bar->timing().first().output, 1);
    // 60 1/min on 0..359 is 360 positions/s: 10 ms moves the edges 3.6 early.
    QVERIFY(std::abs(bar->timing().first().shiftOn - 3.6) < 1e-6);
    const QList<QRectF> strip = diagram->timingRects(1, 0);
    const QList<QRectF> bar1 = diagram->camRects(1, 0);
    QVERIFY(!strip.isEmpty() && !bar1.isEmpty());
    QVERIFY(strip.first().top() >= bar1.first().bottom());  // under the cam
    QVERIFY(strip.first().left() < bar1.first().left());    // switched early
    QVERIFY2(!bar->summary().contains(QLatin1String("warning")), qPrintable(bar->summary()));

    // A minimum pulse (track table, PC only) longer than the cam lasts.
    cams->setMinimumPulse(1, 100000);
    QVERIFY2(bar->summary().contains(QLatin1String("minimum pulse")), qPrintable(bar->summary()));
    QVERIFY(!bar->timing().first().problems.isEmpty());
    QCOMPARE(camConWorkspace(*shell)->changedCount(), 1);  // the dead time; the pulse is no edit

    bar->setTimingShown(false);
    QVERIFY(!diagram->timingShown());
    QVERIFY(diagram->timingRects(1, 0).isEmpty());
}

void CamPageTest::failedReadOnDeadLineKeepsEditsAndSaysWhy() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    // The sections' reads of the start run on the old line first.
    QVERIFY(waitForSections(*shell));
    CamDocument* cams = camConWorkspace(*shell)->cams();
    Cam cam = cams->track(0, 1).cams.first();
    cam.off += 3;
    cams->setCam(0, 1, 0, cam);
    const int changes = camConWorkspace(*shell)->changedCount();
    QVERIFY(changes > 0);

    // The same line now loses every answer (a pulled cable).
    DeviceSession* session = shell->session();
    comm::AsciiProtocolSettings link(comm::Framing::Standard);
    link.fromMap(session->protocol().toMap());
    link.ascii.timeoutMs = 100;
    link.ascii.retries = 1;
    comm::ConnectionSettings dead;
    dead.port = QStringLiteral("sim:throttle=0;dead=1");
    session->connectTo(dead, std::make_shared<comm::AsciiProtocolSettings>(link));
    QTRY_VERIFY_WITH_TIMEOUT(session->isOnline(), kDeviceTimeoutMs);

    std::optional<Status> read;
    camConWindow(shell->window())->camPage()->readProgram(0, [&](const Status& s) { read = s; });
    QTRY_VERIFY_WITH_TIMEOUT(read.has_value(), kDeviceTimeoutMs);
    QVERIFY(!read->ok());
    QVERIFY(!read->error().message.isEmpty());
    QVERIFY2(shell->window()->lastMessage().contains(QStringLiteral("Your edits are kept")),
             qPrintable(shell->window()->lastMessage()));
    QCOMPARE(cams->track(0, 1).cams.first(), cam);
    QCOMPARE(camConWorkspace(*shell)->changedCount(), changes);
}

void CamPageTest::closingWithUnwrittenChangesCountsThem() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    MainWindow* window = shell->window();
    QVERIFY(!window->windowTitle().contains(QStringLiteral("not written")));
    CamDocument* cams = camConWorkspace(*shell)->cams();
    Cam cam = cams->track(0, 1).cams.first();
    cam.on += 2;
    cams->setCam(0, 1, 0, cam);
    QVERIFY(window->windowTitle().contains(QStringLiteral("[1 change not written]")));
    QVERIFY(window->isWindowModified());
    // The question comes first; cancel it and the window stays.
    QTimer::singleShot(0, window, [] {
        if (QWidget* box = QApplication::activeModalWidget()) box->close();
    });
    QVERIFY(!window->confirmClose());
}

QTEST_MAIN(CamPageTest)
#include "tst_cam_page.moc"
