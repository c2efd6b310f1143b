// The shell against the in-process simulator through the real CommWorker:
// read, edit, write, compare, backup/restore, a failing line.
#include "comm/camcon/ascii/ascii_protocol.h"
#include "shell_fixture.h"

#include "model/camcon/eeprom_image_file.h"
#include "ui/camcon/analogue_cams_page.h"
#include "ui/camcon/backup_wizard.h"
#include "ui/camcon/cam_page.h"
#include "ui/camcon/cameditor/cam_diagram_widget.h"
#include "ui/camcon/cameditor/cam_editor_widget.h"
#include "ui/camcon/compare_dialog.h"
#include "ui/camcon/compare_programs_dialog.h"
#include "ui/camcon/dead_time_modes_page.h"
#include "ui/camcon/dead_times_model.h"
#include "ui/camcon/dead_times_page.h"
#include "ui/camcon/eeprom_lock_page.h"
#include "ui/camcon/program_diff_view.h"
#include "ui/camcon/timing_bar.h"
#include "ui/camcon/users_page.h"
#include "ui/device_session.h"
#include "ui/language.h"
#include "ui/progress_page.h"

#include <QAbstractButton>
#include <QCheckBox>
#include <QFile>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

using namespace cambench;
using namespace cambench::test;

class MainWindowTest : public QObject {
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
    void compareWritesOnlySelectedItems();
    void compareProgramsDrawsAndListsTheDifferences();
    void compareProgramsWritesOnlyTheCheckedDifferences();
    void timingAtSpeedIsDrawnUnderTheCamsAndWarns();
    void deadTimeEditIsWrittenInTenthsOfMs_data() { protocolRows(); }
    void deadTimeEditIsWrittenInTenthsOfMs();
    void sectionsFollowTheProtocolsCapabilities_data() { protocolRows(); }
    void sectionsFollowTheProtocolsCapabilities();
    void dataOnlyTheTableInterfaceHasIsEditedAndWritten();
    void tablePageAsksBeforeAReadReplacesEdits();
    void lockedEepromIsShownAsAPlainWarning();
    void backupAndRestoreThroughWizard();
    void wizardRestoresAnotherDevicesImageOnlyAsItsReplacement();
    void restoreRefusesDamagedImage();
    void failedReadOnDeadLineKeepsEditsAndSaysWhy();
    void closingWithUnwrittenChangesCountsThem();
};

void MainWindowTest::startReadsIdentityAndProgramZero() {
    QFETCH(QString, protocol);
    auto shell = startOnSimulator(QStringLiteral("sim:throttle=0"), protocol);
    QVERIFY(shell);
    QVERIFY(camConWorkspace(*shell)->infoFromDevice());
    QCOMPARE(camConWorkspace(*shell)->info().epromDate, QStringLiteral("11.10.1994"));
    QVERIFY(camConWorkspace(*shell)->cams()->hasDeviceCopy(0));
    QVERIFY(!camConWorkspace(*shell)->cams()->program(0).tracks.isEmpty());
    QCOMPARE(camConWorkspace(*shell)->changedCount(), 0);
}

void MainWindowTest::editedCamWrittenAndReadBackEqualsEdit() {
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

void MainWindowTest::compareWritesOnlySelectedItems() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QVERIFY(waitForSections(*shell));
    CamDocument* cams = camConWorkspace(*shell)->cams();
    cams->setDeadTime(2, cams->deadTime(2) + 15);
    Cam cam = cams->track(0, 1).cams.first();
    cam.on += 1;
    cams->setCam(0, 1, 0, cam);

    CompareDialog* compare = camConWindow(shell->window())->openCompare();
    QTRY_VERIFY_WITH_TIMEOUT(!compare->isReading(), kDeviceTimeoutMs);
    QCOMPARE(compare->differenceCount(), 2);
    compare->checkOnly({WorkspaceItem::deadTime(2)});
    std::optional<WriteResult> result;
    connect(compare, &CompareDialog::writeFinished, this,
            [&](const WriteResult& r) { result = r; });
    compare->writeChecked();
    QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), kDeviceTimeoutMs);
    QVERIFY(result->ok());
    QCOMPARE(result->value().count(usecases::WriteState::Written), 1);
    QVERIFY(result->value().complete());
    QVERIFY2(compare->reportText().contains(QStringLiteral("1 written")),
             qPrintable(compare->reportText()));
    // The cam edit was not selected and is still a difference.
    QCOMPARE(compare->differenceCount(), 1);
    QCOMPARE(camConWorkspace(*shell)->deviceDeadTime(2), cams->deadTime(2));
    QCOMPARE(cams->trackState(0, 1), ChangeState::Edited);
    compare->close();
}

void MainWindowTest::compareProgramsDrawsAndListsTheDifferences() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    CamDocument* cams = camConWorkspace(*shell)->cams();
    const Cam before = cams->track(0, 1).cams.first();
    Cam after = before;
    after.off += 10;
    cams->setCam(0, 1, 0, after);

    CompareProgramsDialog* dialog = camConWindow(shell->window())->openComparePrograms();
    dialog->setSide(0, CompareProgramsDialog::Source::Device, 0);
    dialog->setSide(1, CompareProgramsDialog::Source::Edited, 0);
    QSignalSpy compared(dialog, &CompareProgramsDialog::compared);
    dialog->compare();
    QVERIFY(compared.wait(kDeviceTimeoutMs));
    QVERIFY2(compared.first().first().toBool(), qPrintable(dialog->summary()));
    QCOMPARE(dialog->differenceTexts(),
             QStringList{QStringLiteral("output 1, cam 1: %1..%2 → %1..%3")
                             .arg(before.on)
                             .arg(before.off)
                             .arg(after.off)});
    QVERIFY2(dialog->summary().contains(QLatin1String("the device, program 0, read at")),
             qPrintable(dialog->summary()));
    // The list selects in the diagram.
    dialog->list()->setCurrentRow(0);
    QCOMPARE(dialog->view()->selected(), 0);
    // Outputs without a difference fold away on request.
    QVERIFY(dialog->view()->shownOutputs().size() > 1);
    dialog->findChild<QCheckBox*>()->setChecked(true);
    QCOMPARE(dialog->view()->shownOutputs(), QList<int>{1});

    // A side that cannot be read is said, and nothing is drawn.
    dialog->setSide(0, CompareProgramsDialog::Source::ProjectFile, 0);
    compared.clear();
    dialog->compare();
    if (compared.isEmpty()) QVERIFY(compared.wait(kDeviceTimeoutMs));
    QVERIFY(!compared.first().first().toBool());
    QVERIFY2(dialog->summary().contains(QLatin1String("Choose the project file")),
             qPrintable(dialog->summary()));
    QVERIFY(dialog->differenceTexts().isEmpty());
    dialog->close();
}

void MainWindowTest::compareProgramsWritesOnlyTheCheckedDifferences() {
    auto shell = startOnSimulator(QStringLiteral("sim:throttle=0"));
    QVERIFY(shell);
    CamDocument* cams = camConWorkspace(*shell)->cams();
    // Two edits on this PC, on two outputs; only the first gets checked.
    const Cam before = cams->track(0, 1).cams.first();
    Cam moved = before;
    moved.off += 10;
    cams->setCam(0, 1, 0, moved);
    int other = 2;
    while (other <= cams->outputCount() && !cams->track(0, other).cams.isEmpty()) ++other;
    QVERIFY(other <= cams->outputCount());
    cams->insertCam(0, other, {5, 9});

    CompareProgramsDialog* dialog = camConWindow(shell->window())->openComparePrograms();
    dialog->setSide(0, CompareProgramsDialog::Source::Device, 0);
    dialog->setSide(1, CompareProgramsDialog::Source::Edited, 0);
    QSignalSpy compared(dialog, &CompareProgramsDialog::compared);
    dialog->compare();
    QTRY_VERIFY_WITH_TIMEOUT(!compared.isEmpty() && !dialog->isReading(), kDeviceTimeoutMs);
    QCOMPARE(dialog->differenceTexts().size(), 2);
    QVERIFY(!dialog->canApply());  // nothing checked yet
    dialog->setChecked(0, true);
    QVERIFY(dialog->canApply());

    QSignalSpy applied(dialog, &CompareProgramsDialog::applied);
    QString question;
    NextDialog<QMessageBox> confirm([&question](QMessageBox* box) {
        question = box->text();
        for (QAbstractButton* button : box->buttons())
            if (box->buttonRole(button) == QMessageBox::AcceptRole) button->click();
    });
    dialog->applyChecked();
    QCOMPARE(confirm.answered(), 1);
    QVERIFY2(question.contains(QLatin1String("program 0: output 1 (1 difference")),
             qPrintable(question));
    QVERIFY(applied.wait(kDeviceTimeoutMs));
    QVERIFY2(applied.first().first().toBool(), qPrintable(dialog->lastApplyResult()));
    // Output 1 is on the device now, the unchecked edit is still only here.
    QCOMPARE(cams->deviceTrack(0, 1)->cams.first(), moved);
    QCOMPARE(cams->trackState(0, 1), ChangeState::Unchanged);
    QCOMPARE(cams->trackState(0, other), ChangeState::Edited);
    // Both sides read again: the one difference left.
    QTRY_COMPARE_WITH_TIMEOUT(dialog->differenceTexts().size(), 1, kDeviceTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(!dialog->isReading(), kDeviceTimeoutMs);
    QVERIFY(dialog->differenceTexts().first().contains(QStringLiteral("output %1").arg(other)));
    // What the write did stays said above the new comparison.
    QVERIFY2(dialog->summary().contains(QLatin1String("1 written")), qPrintable(dialog->summary()));
    dialog->close();
}

void MainWindowTest::timingAtSpeedIsDrawnUnderTheCamsAndWarns() {
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

void MainWindowTest::deadTimeEditIsWrittenInTenthsOfMs() {
    QFETCH(QString, protocol);
    auto shell = startOnSimulator(QStringLiteral("sim:throttle=0"), protocol);
    QVERIFY(shell);
    QVERIFY(waitForSections(*shell));
    DeadTimesPage* page = camConWindow(shell->window())->deadTimesPage();
    DeadTimesModel* model = page->model();
    const QModelIndex cell = model->index(0, DeadTimesModel::DeadTimeColumn);
    QVERIFY(model->setData(cell, 12.3));
    QCOMPARE(camConWorkspace(*shell)->cams()->deadTime(1), 123);
    QVERIFY(model->data(cell).toString().startsWith(QStringLiteral("● ")));
    // Above the device's maximum (?GTZKMAX) is refused.
    QVERIFY(!model->setData(cell, camConWorkspace(*shell)->info().maxDeadTime / 10.0 + 0.1));

    std::optional<WriteResult> result;
    page->writeChanges([&](const WriteResult& r) { result = r; });
    QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), kDeviceTimeoutMs);
    QVERIFY(result->ok());
    QCOMPARE(result->value().count(usecases::WriteState::Written), 1);
    QVERIFY(result->value().complete());
    QVERIFY(!model->data(cell).toString().startsWith(QStringLiteral("● ")));

    page->readFromDevice();
    QTRY_COMPARE_WITH_TIMEOUT(camConWorkspace(*shell)->deviceDeadTime(1), 123, kDeviceTimeoutMs);
}

void MainWindowTest::backupAndRestoreThroughWizard() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString image = dir.filePath(QStringLiteral("backup.json"));
    const QString safety = dir.filePath(QStringLiteral("safety.json"));

    BackupWizard* backup = camConWindow(shell->window())->openBackupWizard();
    backup->setMode(BackupWizard::Mode::Backup);
    backup->setPath(image);
    backup->next();
    QCOMPARE(backup->currentId(), int(BackupWizard::RunPage));
    QTRY_VERIFY_WITH_TIMEOUT(backup->progressPage()->isComplete(), kDeviceTimeoutMs);
    QVERIFY2(backup->progressPage()->reportText().contains(QStringLiteral("Backup complete")),
             qPrintable(backup->progressPage()->reportText()));
    QVERIFY(loadEepromImage(image).ok());
    backup->close();

    BackupWizard* restore = camConWindow(shell->window())->openBackupWizard();
    QSignalSpy restored(restore, &BackupWizard::restored);
    restore->setMode(BackupWizard::Mode::Restore);
    restore->setPath(image);
    restore->next();
    QCOMPARE(restore->currentId(), int(BackupWizard::CheckPage));
    QVERIFY(restore->checkText().contains(QStringLiteral("matches")));
    restore->setSafetyBackupPath(safety);
    NextDialog<QMessageBox> erase([](QMessageBox* box) {
        for (QAbstractButton* button : box->buttons()) {
            if (box->buttonRole(button) == QMessageBox::DestructiveRole) button->click();
        }
    });
    restore->next();
    QCOMPARE(erase.answered(), 1);
    QTRY_VERIFY_WITH_TIMEOUT(restore->progressPage()->isComplete(), kDeviceTimeoutMs);
    const QString report = restore->progressPage()->reportText();
    QVERIFY2(report.contains(QStringLiteral("Restore complete")), qPrintable(report));
    QVERIFY(report.contains(QStringLiteral("0 failed")));
    QCOMPARE(restored.size(), 1);
    QVERIFY(loadEepromImage(safety).ok());
    restore->close();
}

// Issue 35, item 8: an image of another device (here device number 5) is
// restored only when the person says this device replaces that one; the
// question shows both identities. Declined, the wizard stays and nothing is
// erased; accepted, the erase question follows and the restore runs.
void MainWindowTest::wizardRestoresAnotherDevicesImageOnlyAsItsReplacement() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QTemporaryDir dir;
    const QString image = dir.filePath(QStringLiteral("other.json"));
    BackupWizard* backup = camConWindow(shell->window())->openBackupWizard();
    backup->setMode(BackupWizard::Mode::Backup);
    backup->setPath(image);
    backup->next();
    QTRY_VERIFY_WITH_TIMEOUT(backup->progressPage()->isComplete(), kDeviceTimeoutMs);
    backup->close();
    Result<EepromImage> taken = loadEepromImage(image);
    QVERIFY(taken.ok());
    EepromImage other = *taken;
    other.device.deviceNumber = 5;
    QVERIFY(saveEepromImage(image, other).ok());

    BackupWizard* restore = camConWindow(shell->window())->openBackupWizard();
    QSignalSpy restored(restore, &BackupWizard::restored);
    restore->setMode(BackupWizard::Mode::Restore);
    restore->setPath(image);
    restore->next();
    QCOMPARE(restore->currentId(), int(BackupWizard::CheckPage));
    QVERIFY(restore->checkText().contains(QStringLiteral("does NOT match")));
    restore->setSafetyBackupPath(dir.filePath(QStringLiteral("safety.json")));
    QString question;
    {
        NextDialog<QMessageBox> decline([&question](QMessageBox* box) {
            question = box->objectName() + QLatin1Char('\n') + box->informativeText();
            box->button(QMessageBox::Cancel)->click();
        });
        restore->next();
        QCOMPARE(decline.answered(), 1);
    }
    QVERIFY2(question.startsWith(QStringLiteral("replacementQuestion")), qPrintable(question));
    QVERIFY2(question.contains(QStringLiteral("device: backup 5, this device 0  ← differs")),
             qPrintable(question));
    QCOMPARE(restore->currentId(), int(BackupWizard::CheckPage));
    QCOMPARE(restored.size(), 0);

    // Accepted: then the erase question, then the restore.
    QStringList asked;
    QTimer answer;
    answer.setInterval(10);
    connect(&answer, &QTimer::timeout, this, [&asked] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box) return;
        asked << box->objectName();
        for (QAbstractButton* button : box->buttons())
            if (box->buttonRole(button) == QMessageBox::DestructiveRole) {
                button->click();
                return;
            }
    });
    answer.start();
    restore->next();
    answer.stop();
    QCOMPARE(asked.size(), 2);
    QCOMPARE(asked.at(0), QStringLiteral("replacementQuestion"));
    QTRY_VERIFY_WITH_TIMEOUT(restore->progressPage()->isComplete(), kDeviceTimeoutMs);
    QVERIFY2(restore->progressPage()->reportText().contains(QStringLiteral("Restore complete")),
             qPrintable(restore->progressPage()->reportText()));
    QCOMPARE(restored.size(), 1);
    restore->close();
}

void MainWindowTest::restoreRefusesDamagedImage() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("damaged.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{\"format\":\"cambench-eeprom-image\",\"version\":1,\"blocks\":[]}");
    file.close();
    BackupWizard* restore = camConWindow(shell->window())->openBackupWizard();
    restore->setMode(BackupWizard::Mode::Restore);
    restore->setPath(path);
    // The refusal is a message box; answer it so the test goes on.
    QTimer::singleShot(0, restore, [] {
        if (QWidget* box = QApplication::activeModalWidget()) box->close();
    });
    restore->next();
    QCOMPARE(restore->currentId(), int(BackupWizard::ChoosePage));
    restore->close();
}

void MainWindowTest::failedReadOnDeadLineKeepsEditsAndSaysWhy() {
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

void MainWindowTest::closingWithUnwrittenChangesCountsThem() {
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

void MainWindowTest::sectionsFollowTheProtocolsCapabilities() {
    QFETCH(QString, protocol);
    auto shell = startOnSimulator(QStringLiteral("sim:throttle=0"), protocol);
    QVERIFY(shell);
    MainWindow* window = shell->window();
    const bool ascii = protocol == QLatin1String("standard");
    CapabilityGate* users = gateOf(window, camConWindow(window)->usersPage());
    CapabilityGate* modes = gateOf(window, window->findChild<DeadTimeModesPage*>());
    CapabilityGate* lock = gateOf(window, window->findChild<EepromLockPage*>());
    QVERIFY(users && modes && lock);
    QTRY_COMPARE_WITH_TIMEOUT(users->isAvailable(), ascii, kDeviceTimeoutMs);
    QTRY_COMPARE_WITH_TIMEOUT(lock->isAvailable(), !ascii, kDeviceTimeoutMs);
    // 3964R e38 cannot address the dead-time mode words.
    QTRY_COMPARE_WITH_TIMEOUT(modes->isAvailable(), protocol == QLatin1String("3964r-n96"),
                              kDeviceTimeoutMs);
    // A section the protocol lacks says which protocol has it.
    const QString why = ascii ? modes->reason() : users->reason();
    QVERIFY2(why.contains(ascii ? QLatin1String("table interface") : QLatin1String("ASCII")),
             qPrintable(why));
    if (protocol == QLatin1String("3964r-e38"))
        QVERIFY2(modes->reason().contains(QLatin1String("3964R n96")), qPrintable(modes->reason()));
    // The Device menu's backups follow the Backup section.
    QAction* backup = nullptr;
    for (QAction* action : window->findChildren<QAction*>())
        if (action->text() == QStringLiteral("&Backup and restore…")) backup = action;
    QVERIFY(backup);
    QTRY_COMPARE_WITH_TIMEOUT(backup->isEnabled(), ascii, kDeviceTimeoutMs);
}

void MainWindowTest::dataOnlyTheTableInterfaceHasIsEditedAndWritten() {
    auto shell = startOnSimulator(QStringLiteral("sim:throttle=0"), QStringLiteral("3964r-n96"));
    QVERIFY(shell);
    auto* modes = shell->window()->findChild<DeadTimeModesPage*>();
    QTRY_VERIFY_WITH_TIMEOUT(modes->onDevice().size() == 32, kDeviceTimeoutMs);
    QCOMPARE(modes->edited(2).mode, DeadTimeMode::SeparateOnOff);
    const OutputDeadTime wanted{DeadTimeMode::SeparateOnOff, 0, 35, 47};
    modes->setEdited(5, wanted);
    QCOMPARE(modes->differences().size(), 1);
    std::optional<WriteResult> result;
    modes->writeChanges([&](const WriteResult& r) { result = r; });
    QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), kDeviceTimeoutMs);
    QVERIFY2(result->ok() && (*result)->complete(), qPrintable(writeDetails(*result)));
    QCOMPARE((*result)->count(usecases::WriteState::Written), 1);
    modes->setEdited(5, {});
    modes->readFromDevice();
    QTRY_COMPARE_WITH_TIMEOUT(modes->edited(5), wanted, kDeviceTimeoutMs);
    QVERIFY(modes->differences().isEmpty());

    auto* analogue = shell->window()->findChild<AnalogueCamsPage*>();
    QTRY_COMPARE_WITH_TIMEOUT(analogue->onDevice().points.size(), 3, kDeviceTimeoutMs);
    const AnalogueCamTrack curve{1, {{10, 100}, {20, 200}}};
    analogue->setEdited(curve);
    result.reset();
    analogue->writeChanges([&](const WriteResult& r) { result = r; });
    QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), kDeviceTimeoutMs);
    QVERIFY2(result->ok() && (*result)->complete(), qPrintable(writeDetails(*result)));
    QCOMPARE((*result)->count(usecases::WriteState::Written), 1);
    analogue->setEdited({1, {}});
    analogue->readFromDevice();
    QTRY_COMPARE_WITH_TIMEOUT(analogue->edited(), curve, kDeviceTimeoutMs);
}

void MainWindowTest::tablePageAsksBeforeAReadReplacesEdits() {
    auto shell = startOnSimulator(QStringLiteral("sim:throttle=0"), QStringLiteral("3964r-n96"));
    QVERIFY(shell);
    auto* modes = shell->window()->findChild<DeadTimeModesPage*>();
    QTRY_VERIFY_WITH_TIMEOUT(modes->onDevice().size() == 32, kDeviceTimeoutMs);
    const OutputDeadTime edited{DeadTimeMode::SeparateOnOff, 0, 35, 47};
    modes->setEdited(5, edited);
    QPushButton* read = nullptr;
    for (QPushButton* button : modes->findChildren<QPushButton*>())
        if (button->text() == QLatin1String("Read from device")) read = button;
    QVERIFY(read);
    const auto answer = [](QMessageBox::StandardButton choice) {
        return NextDialog<QMessageBox>(
            [choice](QMessageBox* box) { box->button(choice)->click(); });
    };
    {
        auto no = answer(QMessageBox::No);
        read->click();
        QTRY_COMPARE_WITH_TIMEOUT(no.answered(), 1, kDeviceTimeoutMs);
    }
    QCOMPARE(modes->edited(5), edited);
    {
        auto yes = answer(QMessageBox::Yes);
        read->click();
        QTRY_COMPARE_WITH_TIMEOUT(yes.answered(), 1, kDeviceTimeoutMs);
    }
    QTRY_COMPARE_WITH_TIMEOUT(modes->edited(5), modes->onDevice().value(5), kDeviceTimeoutMs);
    QVERIFY(modes->differences().isEmpty());
}

void MainWindowTest::lockedEepromIsShownAsAPlainWarning() {
    auto shell = startOnSimulator(QStringLiteral("sim:throttle=0"), QStringLiteral("3964r-e38"));
    QVERIFY(shell);
    auto* lock = shell->window()->findChild<EepromLockPage*>();
    QTRY_VERIFY_WITH_TIMEOUT(lock->locked().has_value(), kDeviceTimeoutMs);
    QVERIFY(!*lock->locked());
    QVERIFY(!lock->warningShown());
    lock->setLocked(true);
    QTRY_VERIFY_WITH_TIMEOUT(lock->locked().value_or(false), kDeviceTimeoutMs);
    QVERIFY(lock->warningShown());
    QVERIFY(lock->warningText().contains(QStringLiteral("RAM only")));
    QVERIFY2(shell->window()->lastMessage().contains(QStringLiteral("RAM only")),
             qPrintable(shell->window()->lastMessage()));
}

QTEST_MAIN(MainWindowTest)
#include "tst_main_window.moc"
