// Issue 6, point 4: nothing unwritten is lost. Every read or open that would
// replace edits asks first (keep mine / take the device's / cancel, per
// section), also when the edits were made while the read was running, and
// the undo history survives a failed write.
#include "pty_simulator.h"

#include "model/camcon/project_file.h"
#include "ui/camcon/cam_page.h"
#include "ui/camcon/device_writer.h"
#include "ui/camcon/project_io.h"
#include "ui/camcon/settings_page.h"
#include "ui/language.h"

#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using namespace cambench;
using namespace cambench::test;

class UnwrittenEditsTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        useTestSettings();
        QVERIFY(setLanguage(QStringLiteral("en")));
    }
    void readProgramWithEditsAsksAndKeepsThem();
    void readProgramTakingTheDevicesIsUndoable();
    void readEverythingWithEditsAsksPerSection();
    void openProjectWithEditsAsksAndCancelChangesNothing();
    void programReadFinishingWhileEditingAsks();
    void readWithoutEditsAsksNothing();
    void undoHistorySurvivesFailedWrite();
};

void UnwrittenEditsTest::readProgramWithEditsAsksAndKeepsThem() {
    PtySimulator sim;
    auto shell = startOnPty(sim);
    QVERIFY(shell);
    CamDocument* cams = camConWorkspace(*shell)->cams();
    cams->setCam(0, 1, 0, {15, 90});
    // Meanwhile someone changes output 2 at the device's panel.
    sim.device().state().cams.insert(0, 1, {100, 120});

    const auto answer = answerReplaceEdits(true);
    std::optional<Status> read;
    camConWindow(shell->window())->camPage()->readProgram(0, [&](const Status& s) { read = s; });
    QTRY_VERIFY_WITH_TIMEOUT(read.has_value(), kDeviceTimeoutMs);
    QCOMPARE(answer->answered(), 1);
    QVERIFY(read->ok());
    QCOMPARE(cams->track(0, 1).cams.first(), (Cam{15, 90}));  // my edit
    QCOMPARE(cams->trackState(0, 1), ChangeState::Edited);
    QCOMPARE(cams->track(0, 2).cams, sim.track(0, 2));  // not edited: the device's
    QCOMPARE(cams->deviceTrack(0, 1)->cams, sim.track(0, 1));
}

void UnwrittenEditsTest::readProgramTakingTheDevicesIsUndoable() {
    PtySimulator sim;
    auto shell = startOnPty(sim);
    QVERIFY(shell);
    CamDocument* cams = camConWorkspace(*shell)->cams();
    cams->setCam(0, 1, 0, {15, 90});
    const auto answer = answerReplaceEdits(false);
    std::optional<Status> read;
    camConWindow(shell->window())->camPage()->readProgram(0, [&](const Status& s) { read = s; });
    QTRY_VERIFY_WITH_TIMEOUT(read.has_value(), kDeviceTimeoutMs);
    QCOMPARE(answer->answered(), 1);
    QCOMPARE(cams->track(0, 1).cams, sim.track(0, 1));
    QCOMPARE(camConWorkspace(*shell)->changedCount(), 0);
    // Taking the device's values is one undo step: the edit comes back.
    cams->undoStack()->undo();
    QCOMPARE(cams->track(0, 1).cams.first(), (Cam{15, 90}));
}

void UnwrittenEditsTest::readEverythingWithEditsAsksPerSection() {
    PtySimulator sim;
    auto shell = startOnPty(sim);
    QVERIFY(shell);
    QVERIFY(waitForSections(*shell));
    Workspace* ws = camConWorkspace(*shell);
    CamDocument* cams = ws->cams();
    cams->setCam(0, 1, 0, {15, 90});
    cams->setDeadTime(2, cams->deadTime(2) + 10);
    QList<EditSection> asked;
    QString camDetails;
    QString deadTimeDetails;
    // Keep the cam edit, take the device's dead times.
    NextDialog<ReplaceEditsDialog> answer([&](ReplaceEditsDialog* dialog) {
        asked = dialog->sections();
        camDetails = dialog->detailsText(EditSection::Cams);
        deadTimeDetails = dialog->detailsText(EditSection::OutputSettings);
        dialog->choose(EditSection::Cams, true);
        dialog->choose(EditSection::OutputSettings, false);
        dialog->accept();
    });
    QSignalSpy done(camConWindow(shell->window()), &CamConWindow::everythingRead);
    camConWindow(shell->window())->readEverything(0);
    QVERIFY(done.wait(kDeviceTimeoutMs));
    QVERIFY(done.first().first().toBool());
    QCOMPARE(asked, (QList<EditSection>{EditSection::Cams, EditSection::OutputSettings}));
    // The question names the outputs, the edit and what the device holds (point 8).
    QVERIFY2(camDetails.startsWith(QStringLiteral("Program 0, output 1: yours 15–90")),
             qPrintable(camDetails));
    QVERIFY2(camDetails.contains(QStringLiteral("the device now holds 10–90")),
             qPrintable(camDetails));
    QVERIFY2(deadTimeDetails.startsWith(QStringLiteral("Output 2 dead time: yours")),
             qPrintable(deadTimeDetails));
    QCOMPARE(cams->track(0, 1).cams.first(), (Cam{15, 90}));
    QCOMPARE(cams->deadTime(2), ws->deviceDeadTime(2));
    // Every program is known now.
    for (int program = 0; program < ws->info().programs; ++program)
        QVERIFY(cams->hasDeviceCopy(program));
}

void UnwrittenEditsTest::openProjectWithEditsAsksAndCancelChangesNothing() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QVERIFY(waitForSections(*shell));
    Workspace* ws = camConWorkspace(*shell);
    CamDocument* cams = ws->cams();
    Project project = projectFromWorkspace(*ws);
    for (CamProgram& program : project.programs) {
        if (program.number == 0) program.tracks[1].cams = {{200, 210}};
    }
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("other.json"));
    QVERIFY(saveProject(path, project).ok());
    cams->setCam(0, 1, 0, {15, 90});
    const int undoSteps = cams->undoStack()->count();

    {
        const auto cancel = cancelReplaceEdits();
        camConWindow(shell->window())->openProjectFile(path);
        QCOMPARE(cancel->answered(), 1);
    }
    QCOMPARE(cams->track(0, 1).cams.first(), (Cam{15, 90}));
    QVERIFY(ws->projectPath().isEmpty());
    QCOMPARE(cams->undoStack()->count(), undoSteps);

    const auto take = answerReplaceEdits(false);
    camConWindow(shell->window())->openProjectFile(path);
    QCOMPARE(take->answered(), 1);
    QCOMPARE(cams->track(0, 1).cams, (QList<Cam>{{200, 210}}));
    QCOMPARE(ws->projectPath(), path);
}

void UnwrittenEditsTest::programReadFinishingWhileEditingAsks() {
    // A slow line: the read is still running when the user edits.
    PtySimulator sim(true, 9600);
    auto shell = startOnPty(sim);
    QVERIFY(shell);
    CamDocument* cams = camConWorkspace(*shell)->cams();
    QCOMPARE(camConWorkspace(*shell)->changedCount(), 0);
    const auto answer = answerReplaceEdits(true);
    std::optional<Status> read;
    camConWindow(shell->window())->camPage()->readProgram(0, [&](const Status& s) { read = s; });
    // No event has been processed: the read's answer cannot be here yet.
    cams->setCam(0, 1, 0, {15, 90});
    QTRY_VERIFY_WITH_TIMEOUT(read.has_value(), kDeviceTimeoutMs);
    QCOMPARE(answer->answered(), 1);
    QCOMPARE(cams->track(0, 1).cams.first(), (Cam{15, 90}));
}

void UnwrittenEditsTest::readWithoutEditsAsksNothing() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    const auto answer = answerReplaceEdits(true);
    std::optional<Status> read;
    camConWindow(shell->window())->camPage()->readProgram(0, [&](const Status& s) { read = s; });
    QTRY_VERIFY_WITH_TIMEOUT(read.has_value(), kDeviceTimeoutMs);
    QVERIFY(read->ok());
    QCOMPARE(answer->answered(), 0);
}

void UnwrittenEditsTest::undoHistorySurvivesFailedWrite() {
    PtySimulator sim;
    auto shell = startOnPty(sim);
    QVERIFY(shell);
    CamDocument* cams = camConWorkspace(*shell)->cams();
    cams->setCam(0, 1, 0, {12, 90});
    cams->setCam(0, 1, 0, {14, 90});
    const int undoSteps = cams->undoStack()->count();
    QVERIFY(undoSteps >= 1);
    sim.fallSilent();  // every command goes unanswered
    std::optional<WriteResult> result;
    camConWindow(shell->window())->camPage()->writeProgram(0, [&](const WriteResult& r) {
        result = r;
    });
    QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), kDeviceTimeoutMs);
    QVERIFY(!result->ok() || !result->value().complete());
    QCOMPARE(cams->undoStack()->count(), undoSteps);
    QCOMPARE(cams->track(0, 1).cams.first(), (Cam{14, 90}));
    cams->undoStack()->undo();
    QVERIFY(cams->track(0, 1).cams.first() != (Cam{14, 90}));
}

QTEST_MAIN(UnwrittenEditsTest)
#include "tst_unwritten_edits.moc"
