// Issue 6, points 1–3: what a write reports is what the device holds. The
// GUI on the real QSerialPort against the simulator on a pseudo-terminal;
// the simulator's log of received commands is the witness.
#include "pty_simulator.h"

#include "model/camcon/project_file.h"
#include "ui/camcon/cam_page.h"
#include "ui/camcon/cameditor/cam_editor_widget.h"
#include "ui/camcon/compare_dialog.h"
#include "ui/camcon/device_writer.h"
#include "ui/camcon/settings_page.h"
#include "ui/language.h"
#include "ui/report_dialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QTemporaryDir>
#include <QToolButton>
#include <QUndoStack>
#include <QtTest>

using namespace cambench;
using namespace cambench::test;

namespace {

// What the write's report dialog showed, and that it fit the screen.
struct SeenReport {
    QString summary;
    QString details;
    bool fitsScreen = false;
};

std::unique_ptr<NextDialog<ReportDialog>> recordReport(SeenReport& seen) {
    return std::make_unique<NextDialog<ReportDialog>>([&seen](ReportDialog* dialog) {
        seen.summary = dialog->summary();
        seen.details = dialog->details();
        const QRect screen = dialog->screen()->availableGeometry();
        QWidget* ok = dialog->buttons()->button(QDialogButtonBox::Ok);
        const QRect okOnScreen(ok->mapToGlobal(QPoint(0, 0)), ok->size());
        seen.fitsScreen = dialog->frameGeometry().height() <= screen.height() && ok->isVisible() &&
                          screen.contains(okOnScreen);
        dialog->accept();
    });
}

void triggerWriteProgram(Shell& shell) {
    camConWindow(shell.window())->camPage()->editor()->editorActions().at(1)->trigger();
}

}  // namespace

class WriteTruthTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        useTestSettings();
        QVERIFY(setLanguage(QStringLiteral("en")));
    }
    void writeRefusedHalfwayReportsTheDevicesRealState();
    void editKnownInvalidIsRefusedBeforeAnyCommand();
    void projectFor96OutputsIsRefusedBeforeAnyWriteCommand();
    void aProjectsCommunicationSettingsGoOnlyWhenTicked();
};

void WriteTruthTest::writeRefusedHalfwayReportsTheDevicesRealState() {
    PtySimulator sim;
    auto shell = startOnPty(sim);
    QVERIFY(shell);
    CamDocument* cams = camConWorkspace(*shell)->cams();
    const QList<Cam> before = sim.track(0, 3);
    QCOMPARE(before.size(), 4);
    // Four cams become two others: inserts and deletes on the device.
    Track wanted = cams->track(0, 3);
    wanted.cams = {{20, 60}, {200, 260}};
    cams->replaceTrack(0, wanted, QStringLiteral("test edit"));
    const int undoSteps = cams->undoStack()->count();
    sim.injections().clearLog();
    // The device refuses the second insert ("EEPROM full"), halfway through.
    sim.injections().refuse(0, '!', "NINS", -21, 1);

    SeenReport seen;
    const auto dialog = recordReport(seen);
    std::optional<WriteResult> result;
    camConWindow(shell->window())->camPage()->writeProgram(0, [&](const WriteResult& r) {
        result = r;
    });
    QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), kDeviceTimeoutMs);
    QVERIFY2(result->ok(), qPrintable(writeSummary(*result)));
    QVERIFY(!result->value().complete());
    QVERIFY(sim.commandsReceived() > 0);  // something was sent before the refusal

    // The device copy is what the device holds now, not the edit and not the old cams.
    const QList<Cam> real = sim.track(0, 3);
    QVERIFY(cams->deviceTrack(0, 3).has_value());
    QCOMPARE(cams->deviceTrack(0, 3)->cams, real);
    // The report says it, item by item.
    const usecases::ItemOutcome<Track> outcome = result->value().tracks.first();
    QVERIFY(outcome.state == usecases::WriteState::Failed ||
            outcome.state == usecases::WriteState::ChangedThoughFailed);
    QCOMPARE(outcome.state == usecases::WriteState::ChangedThoughFailed, real != before);
    QVERIFY(outcome.actual.has_value());
    QCOMPARE(outcome.actual->cams, real);
    // The edit and its undo history are still there.
    QCOMPARE(cams->track(0, 3).cams, wanted.cams);
    QCOMPARE(cams->trackState(0, 3), ChangeState::Edited);
    QCOMPARE(cams->undoStack()->count(), undoSteps);
    cams->undoStack()->undo();
    QCOMPARE(cams->track(0, 3).cams, before);
    cams->undoStack()->redo();

    // Through the editor's button a person sees the same in a dialog.
    cams->setCam(0, 3, 0, {25, 60});
    sim.injections().refuse(0, '!', "NINS", -21);
    triggerWriteProgram(*shell);
    QTRY_COMPARE_WITH_TIMEOUT(dialog->answered(), 1, kDeviceTimeoutMs);
    QVERIFY2(seen.fitsScreen, "the report dialog must fit the screen with its OK button");
    QVERIFY2(seen.details.contains(QStringLiteral("output 3")), qPrintable(seen.details));
    QCOMPARE(cams->deviceTrack(0, 3)->cams, sim.track(0, 3));
    // The report can be opened again from the status bar (point 8).
    auto* lastWrite = shell->window()->findChild<QToolButton*>(QStringLiteral("lastWriteReport"));
    QVERIFY(lastWrite);
    QVERIFY2(lastWrite->text().contains(QStringLiteral("NOT complete")),
             qPrintable(lastWrite->text()));
    seen = {};
    const auto again = recordReport(seen);
    lastWrite->click();
    QTRY_COMPARE_WITH_TIMEOUT(again->answered(), 1, kDeviceTimeoutMs);
    QVERIFY2(seen.details.contains(QStringLiteral("output 3")), qPrintable(seen.details));

    // Compare asks the device, and shows what it holds now.
    CompareDialog* compare = camConWindow(shell->window())->openCompare();
    QTRY_VERIFY_WITH_TIMEOUT(!compare->isReading(), kDeviceTimeoutMs);
    QVERIFY2(compare->sourceText().contains(QStringLiteral("read at")),
             qPrintable(compare->sourceText()));
    QCOMPARE(cams->deviceTrack(0, 3)->cams, sim.track(0, 3));
    compare->close();
}

void WriteTruthTest::editKnownInvalidIsRefusedBeforeAnyCommand() {
    PtySimulator sim;
    auto shell = startOnPty(sim);
    QVERIFY(shell);
    CamDocument* cams = camConWorkspace(*shell)->cams();
    // Output 1 holds 10–90 and 180–270; the second cam now overlaps the first.
    QCOMPARE(sim.track(0, 1), (QList<Cam>{{10, 90}, {180, 270}}));
    cams->setCam(0, 1, 1, {80, 270});
    QVERIFY(!cams->problems(0, 1).isEmpty());  // the editor marks it red
    sim.injections().clearLog();

    SeenReport seen;
    const auto dialog = recordReport(seen);
    triggerWriteProgram(*shell);
    QTRY_COMPARE_WITH_TIMEOUT(dialog->answered(), 1, kDeviceTimeoutMs);
    QCOMPARE(sim.commandsReceived(), 0);
    QCOMPARE(sim.track(0, 1), (QList<Cam>{{10, 90}, {180, 270}}));
    QVERIFY2(seen.summary.contains(QStringLiteral("refused")), qPrintable(seen.summary));
    QVERIFY2((seen.summary + seen.details).contains(QStringLiteral("overlap")),
             qPrintable(seen.summary + QLatin1Char('\n') + seen.details));
    QCOMPARE(cams->trackState(0, 1), ChangeState::Edited);
}

void WriteTruthTest::projectFor96OutputsIsRefusedBeforeAnyWriteCommand() {
    PtySimulator sim;
    auto shell = startOnPty(sim);
    QVERIFY(shell);
    const QList<Cam> program0Output1 = sim.track(0, 1);

    // A project made for a 96-output device with positions up to 12499.
    Project project;
    project.device = camConWorkspace(*shell)->info();
    project.device.outputs = 96;
    project.device.deadTimeOutputs = 96;
    project.device.maxPosition = 12499;
    CamProgram program;
    program.number = 0;
    for (int output = 1; output <= 96; ++output) {
        Track track;
        track.output = output;
        track.cams = {{100, 12000}};
        program.tracks.insert(output, track);
    }
    project.programs << program;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("big.json"));
    QVERIFY(saveProject(path, project).ok());
    camConWindow(shell->window())->openProjectFile(path);
    QCOMPARE(camConWorkspace(*shell)->projectPath(), path);
    sim.injections().clearLog();

    SeenReport seen;
    const auto dialog = recordReport(seen);
    triggerWriteProgram(*shell);
    QTRY_COMPARE_WITH_TIMEOUT(dialog->answered(), 1, kDeviceTimeoutMs);
    // Refused as a whole before the first byte of a write: nothing changed.
    QCOMPARE(sim.commandsReceived(), 0);
    QCOMPARE(sim.track(0, 1), program0Output1);
    QVERIFY2(seen.summary.contains(QStringLiteral("33")), qPrintable(seen.summary));
    QVERIFY2(seen.fitsScreen, "the refusal must fit the screen with its OK button");
}

namespace {

// The commands ('!') the device received, by name.
QStringList commandNames(PtySimulator& sim) {
    QStringList names;
    for (const comm::SimInjections::Received& received : sim.injections().received())
        if (received.kind == '!') names << QString::fromLatin1(received.name);
    return names;
}

// The question before the write: what it said; ticks "Also write" or not,
// then presses Write (or Cancel).
std::unique_ptr<NextDialog<QMessageBox>> answerLinkQuestion(QString& said, bool tick,
                                                            bool write = true) {
    return std::make_unique<NextDialog<QMessageBox>>([&said, tick, write](QMessageBox* box) {
        said = box->text() + QLatin1Char('\n') + box->informativeText() + QLatin1Char('\n') +
               box->checkBox()->text();
        QVERIFY(!box->checkBox()->isChecked());  // left out unless ticked
        box->checkBox()->setChecked(tick);
        for (QAbstractButton* button : box->buttons()) {
            const bool accept = box->buttonRole(button) == QMessageBox::AcceptRole;
            if (accept == write) {
                button->click();
                return;
            }
        }
    });
}

}  // namespace

// Issue 39: a table-interface project opened on a CamCon on Standard
// carries protocol 3964R and another device number. The write asks first,
// saying what the next connection would need; unticked they are left out
// and the report names them, ticked they go last; Cancel sends nothing.
void WriteTruthTest::aProjectsCommunicationSettingsGoOnlyWhenTicked() {
    PtySimulator sim;
    auto shell = startOnPty(sim);
    QVERIFY(shell);
    SettingsPage* page = camConWindow(shell->window())->settingsPage();
    const auto writeAndWait = [&](const std::function<void()>& answer) -> WriteResult {
        std::optional<WriteResult> result;
        answer();
        page->writeChanges([&result](const WriteResult& done) { result = done; });
        if (!QTest::qWaitFor([&result] { return result.has_value(); }, kDeviceTimeoutMs))
            return WriteResult(Error::communication(QStringLiteral("the write did not end")));
        return *result;
    };
    // The device's settings are known (the question names the device's values).
    if (!camConWorkspace(*shell)->settings().known()) page->readFromDevice();
    QTRY_VERIFY_WITH_TIMEOUT(camConWorkspace(*shell)->settings().known(), kDeviceTimeoutMs);
    Project project;
    project.device = camConWorkspace(*shell)->info();
    project.settings = {{QStringLiteral("protocol"), qint64(4)},
                        {QStringLiteral("deviceNumber"), qint64(5)},
                        {QStringLiteral("cableLength"), qint64(17)}};
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("table.json"));
    QVERIFY(saveProject(path, project).ok());
    camConWindow(shell->window())->openProjectFile(path);

    // Cancel: nothing at all is sent.
    QString said;
    std::unique_ptr<NextDialog<QMessageBox>> question;
    sim.injections().clearLog();
    const WriteResult cancelled =
        writeAndWait([&] { question = answerLinkQuestion(said, false, false); });
    QCOMPARE(question->answered(), 1);
    QVERIFY(!cancelled.ok());
    QCOMPARE(commandNames(sim), QStringList());
    QVERIFY2(said.contains(QLatin1String("Device number 5, Communication protocol 3964R (the "
                                         "device has Device number 0, Communication protocol "
                                         "Standard)")),
             qPrintable(said));
    QVERIFY2(said.contains(QLatin1String("the next connection to this device needs them")),
             qPrintable(said));

    // Not ticked: the cable length only; the report names what was left out.
    SeenReport seen;
    std::unique_ptr<NextDialog<ReportDialog>> report;
    const WriteResult leftOut = writeAndWait([&] {
        question = answerLinkQuestion(said, false);
        report = recordReport(seen);
    });
    QVERIFY2(leftOut.ok(), qPrintable(leftOut.error().message));
    QCOMPARE(commandNames(sim), QStringList{QStringLiteral("GKL")});
    QVERIFY2(seen.summary.contains(QLatin1String("Communication settings left out")),
             qPrintable(seen.summary));
    QCOMPARE(camConWorkspace(*shell)
                 ->settings()
                 .deviceValue(QStringLiteral("protocol"))
                 .value_or(QVariant())
                 .toLongLong(),
             1);

    // Ticked: the device number, then the protocol, last.
    sim.injections().clearLog();
    const WriteResult written = writeAndWait([&] {
        question = answerLinkQuestion(said, true);
        report = recordReport(seen);
    });
    QVERIFY2(written.ok(), qPrintable(written.error().message));
    QCOMPARE(commandNames(sim), QStringList({QStringLiteral("GNR"), QStringLiteral("GSIO")}));
    QVERIFY2(seen.summary.contains(QLatin1String("the next connection to this device needs "
                                                 "Device number 5, Communication protocol "
                                                 "3964R")),
             qPrintable(seen.summary));
    QCOMPARE(camConWorkspace(*shell)->settings().changedCount(), 0);
}

QTEST_MAIN(WriteTruthTest)
#include "tst_write_truth.moc"
