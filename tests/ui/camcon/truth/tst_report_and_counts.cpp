// Issue 6, points 8 and 9: the PDF report is a record of the device and of
// what is not written; counts add up; the backup's time left is no guess;
// a restore to the very device asks its own "this erases the device".
#include "../camcon_fixture.h"

#include "model/camcon/eeprom_image_file.h"
#include "ui/camcon/backup_wizard.h"
#include "ui/camcon/commissioning_report.h"
#include "ui/camcon/dead_times_page.h"
#include "ui/camcon/device_writer.h"
#include "ui/camcon/print_diagram.h"
#include "ui/camcon/setting_field.h"
#include "ui/camcon/users_page.h"
#include "ui/device_session.h"
#include "ui/language.h"
#include "ui/progress_page.h"
#include "ui/report_pages.h"
#include "ui/theme.h"

#include <QAbstractButton>
#include <QAbstractTextDocumentLayout>
#include <QMessageBox>
#include <QTemporaryDir>
#include <QTextBlock>
#include "comm/device/protocol_registry.h"

#include <QTextDocument>
#include <QtTest>

using namespace cambench;
using namespace cambench::test;

namespace {

std::unique_ptr<Shell> startAndReadEverything() {
    auto shell = startOnSimulator();
    if (!shell) return nullptr;
    QSignalSpy done(camConWindow(shell->window()), &CamConWindow::everythingRead);
    camConWindow(shell->window())->readEverything(0);
    if (!done.wait(kDeviceTimeoutMs) || !done.first().first().toBool()) return nullptr;
    return shell;
}

QString reportText(const Workspace& workspace) {
    QTextDocument document;
    CommissioningReport::build(document, workspace);
    return document.toPlainText();
}

}  // namespace

class ReportAndCountsTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        useTestSettings();
        QVERIFY(setLanguage(QStringLiteral("en")));
    }
    void reportHoldsEverySectionOfTheDevice();
    void reportMarksUnwrittenValues();
    void reportSaysOfflineOnlyWhenOffline();
    void reportDiagramIsDrawnForPrintWithAllOutputs();
    void noHeadingStandsAloneAtAPageFoot();
    void reportMinimumCycleTimeIsInMilliseconds();
    void reportShowsOnlyValuesOfTheConnectedDevice();
    void deadTimeWriteCountsOverTheDevicesOutputs();
    void userWriteCountsTheUnchangedUsers();
    void backupGivesNoGuessedTimeLeft();
    void restoreToTheSameDeviceAsksItsOwnConfirmation();
};

void ReportAndCountsTest::reportHoldsEverySectionOfTheDevice() {
    auto shell = startAndReadEverything();
    QVERIFY(shell);
    const Workspace& ws = *camConWorkspace(*shell);
    const QString text = reportText(ws);
    for (int program = 0; program < ws.info().programs; ++program)
        QVERIFY2(text.contains(QStringLiteral("Program %1").arg(program)),
                 qPrintable(QString::number(program)));
    QVERIFY(text.contains(QStringLiteral("Format A4")));  // program 1's name
    for (const UserCopies::EditedUser& user : ws.users().rows()) {
        QVERIFY(text.contains(user.user.name));
        QVERIFY2(!text.contains(user.user.number), "user numbers are access codes: never printed");
    }
    QVERIFY(text.contains(QStringLiteral("*****")));
    QVERIFY(text.contains(QStringLiteral("Outputs and dead times")));
    QVERIFY(text.contains(QStringLiteral("Glue valve")));
    QVERIFY(text.contains(QStringLiteral("PLC networks")));
    QVERIFY(text.contains(QStringLiteral("O001")));
    QVERIFY(text.contains(QStringLiteral("Settings")));
    QVERIFY(text.contains(QStringLiteral("11.10.1994")));
    QVERIFY(text.contains(QStringLiteral("Read from the device at")));
    QVERIFY(!text.contains(QStringLiteral("offline project")));
    QVERIFY(text.contains(QStringLiteral("Every value in this report is what the device held")));
    QVERIFY(!text.contains(QStringLiteral("Timing at")));  // only when a speed is given

    // Issue 17: with a speed, one timing table per program with cams, at
    // that speed and in its unit.
    {
        QTextDocument timed;
        CommissioningReport::build(timed, ws, {60.0, {}});
        const QString withTiming = timed.toPlainText();
        QVERIFY2(withTiming.contains(QStringLiteral("Timing at 60.0 1/min")),
                 qPrintable(withTiming.right(2000)));
        QVERIFY(withTiming.contains(QStringLiteral("Shortest cam")));
    }

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("report.pdf"));
    QVERIFY(CommissioningReport::write(path, ws).ok());
    QFile pdf(path);
    QVERIFY(pdf.open(QIODevice::ReadOnly));
    QVERIFY(pdf.read(5) == "%PDF-");
}

void ReportAndCountsTest::reportMarksUnwrittenValues() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QVERIFY(waitForSections(*shell));
    CamDocument* cams = camConWorkspace(*shell)->cams();
    const qint32 device = cams->deadTime(2);
    cams->setDeadTime(2, device + 15);
    cams->setCam(0, 1, 0, {12, 90});
    const QString text = reportText(*camConWorkspace(*shell));
    QVERIFY2(text.contains(QStringLiteral("2 value")) &&
                 text.contains(QStringLiteral("edited on this PC and NOT written")),
             qPrintable(text.left(400)));
    QVERIFY2(text.contains(QStringLiteral("● %1 ms (device: %2 ms)")
                               .arg(QLocale().toString((device + 15) / 10.0, 'f', 1),
                                    QLocale().toString(device / 10.0, 'f', 1))),
             qPrintable(text));
    QVERIFY(text.contains(QStringLiteral("● 12–90, 180–270 (device: 10–90, 180–270)")));
    // A program not read is said to be unknown, not shown as empty.
    QVERIFY(text.contains(QStringLiteral("Not read from the device: its content is unknown.")));
}

void ReportAndCountsTest::reportSaysOfflineOnlyWhenOffline() {
    Workspace offline;
    DeviceInfo info;
    info.outputs = 8;
    info.programs = 2;
    info.deadTimeOutputs = 8;
    offline.setInfo(info, false);
    QVERIFY(reportText(offline).contains(QStringLiteral("offline project")));
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QVERIFY(!reportText(*camConWorkspace(*shell)).contains(QStringLiteral("offline project")));
}

void ReportAndCountsTest::reportDiagramIsDrawnForPrintWithAllOutputs() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    applyTheme(true);  // whatever the screen uses, paper is white
    const CamDocument& cams = *camConWorkspace(*shell)->cams();
    const QImage outputs1to32 = printDiagram(cams, 0, 1, 32, 1000);
    const QImage outputs1to8 = printDiagram(cams, 0, 1, 8, 1000);
    applyTheme(false);
    // One row per output: 24 more outputs, 24 more rows of the same height.
    QVERIFY(outputs1to32.height() > outputs1to8.height());
    QCOMPARE((outputs1to32.height() - outputs1to8.height()) % 24, 0);
    QCOMPARE(outputs1to32.pixelColor(0, 0), QColor(Qt::white));
    QCOMPARE(outputs1to32.pixelColor(outputs1to32.width() - 1, outputs1to32.height() - 1),
             QColor(Qt::white));
}

void ReportAndCountsTest::deadTimeWriteCountsOverTheDevicesOutputs() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QVERIFY(waitForSections(*shell));
    const DeviceInfo& info = camConWorkspace(*shell)->info();
    CamDocument* cams = camConWorkspace(*shell)->cams();
    cams->setDeadTime(3, cams->deadTime(3) + 5);
    DeadTimesPage* page = camConWindow(shell->window())->deadTimesPage();
    // Differences are counted over the device's outputs, nothing beyond.
    QCOMPARE(page->differences().size(), 1);
    QCOMPARE(page->itemCount(), info.deadTimeOutputs + info.outputs);
    std::optional<WriteResult> result;
    page->writeChanges([&](const WriteResult& r) { result = r; });
    QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), kDeviceTimeoutMs);
    QVERIFY(result->ok());
    QCOMPARE(result->value().total(), 1);
    QCOMPARE(result->value().count(usecases::WriteState::Written), 1);
    const QString message = shell->window()->lastMessage();
    QVERIFY2(message.contains(
                 QStringLiteral("%1 other item").arg(info.deadTimeOutputs + info.outputs - 1)),
             qPrintable(message));
}

void ReportAndCountsTest::userWriteCountsTheUnchangedUsers() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QVERIFY(waitForSections(*shell));
    Workspace* ws = camConWorkspace(*shell);
    const int users = int(ws->users().size());
    QVERIFY(users >= 2);
    User renamed = ws->users().row(0).user;
    renamed.name += QStringLiteral("X");
    ws->users().set(0, renamed);
    std::optional<WriteResult> result;
    camConWindow(shell->window())->usersPage()->writeChanges([&](const WriteResult& r) {
        result = r;
    });
    QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), kDeviceTimeoutMs);
    QVERIFY2(result->ok() && result->value().complete(), qPrintable(writeSummary(*result)));
    QCOMPARE(result->value().count(usecases::WriteState::Written), 1);
    const QString message = shell->window()->lastMessage();
    // The users not written are counted as what they are: already on the device.
    QVERIFY2(message.contains(QStringLiteral("%1 other item").arg(users - 1)), qPrintable(message));
    QCOMPARE(ws->changedCount(), 0);
}

void ReportAndCountsTest::backupGivesNoGuessedTimeLeft() {
    auto shell = startOnSimulator(QStringLiteral("sim:baud=115200"));
    QVERIFY(shell);
    QTemporaryDir dir;
    BackupWizard* wizard = camConWindow(shell->window())->openBackupWizard();
    wizard->setMode(BackupWizard::Mode::Backup);
    wizard->setPath(dir.filePath(QStringLiteral("backup.json")));
    QStringList seen;
    connect(&shell->session()->worker(), &comm::JobRunner::jobProgress, this,
            [&] { seen << wizard->progressPage()->etaLabelText(); });
    wizard->next();
    QTRY_VERIFY_WITH_TIMEOUT(wizard->progressPage()->isComplete(), kDeviceTimeoutMs);
    QVERIFY(!seen.isEmpty());
    for (const QString& text : seen)
        QVERIFY2(
            !text.contains(QStringLiteral("left")) || text.contains(QStringLiteral("No time left")),
            qPrintable(text));
    QVERIFY(wizard->progressPage()->reportText().contains(QStringLiteral("Backup complete")));
    // With a known total, the time left comes from the measured rate.
    QCOMPARE(ProgressPage::etaText(2000, 50, 100), QStringLiteral("about 2 s left"));
    wizard->close();
}

void ReportAndCountsTest::restoreToTheSameDeviceAsksItsOwnConfirmation() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QTemporaryDir dir;
    const QString image = dir.filePath(QStringLiteral("same.json"));
    BackupWizard* backup = camConWindow(shell->window())->openBackupWizard();
    backup->setMode(BackupWizard::Mode::Backup);
    backup->setPath(image);
    backup->next();
    QTRY_VERIFY_WITH_TIMEOUT(backup->progressPage()->isComplete(), kDeviceTimeoutMs);
    backup->close();

    BackupWizard* restore = camConWindow(shell->window())->openBackupWizard();
    restore->setMode(BackupWizard::Mode::Restore);
    restore->setPath(image);
    restore->next();
    QCOMPARE(restore->currentId(), int(BackupWizard::CheckPage));
    QVERIFY(restore->checkText().contains(QStringLiteral("matches")));
    QString asked;
    {
        // Declined: the wizard stays, nothing is erased.
        NextDialog<QMessageBox> decline([&asked](QMessageBox* box) {
            asked = box->text();
            box->button(QMessageBox::Cancel)->click();
        });
        restore->next();
        QCOMPARE(decline.answered(), 1);
    }
    QVERIFY2(asked.contains(QStringLiteral("erases the device")), qPrintable(asked));
    QCOMPARE(restore->currentId(), int(BackupWizard::CheckPage));
    {
        NextDialog<QMessageBox> confirm([](QMessageBox* box) {
            for (QAbstractButton* button : box->buttons()) {
                if (box->buttonRole(button) == QMessageBox::DestructiveRole) button->click();
            }
        });
        QSignalSpy restored(restore, &BackupWizard::restored);
        const auto answer = answerReplaceEdits(false);
        restore->next();
        QCOMPARE(confirm.answered(), 1);
        QTRY_VERIFY_WITH_TIMEOUT(restore->progressPage()->isComplete(), kDeviceTimeoutMs);
        QVERIFY2(restore->progressPage()->reportText().contains(QStringLiteral("Restore complete")),
                 qPrintable(restore->progressPage()->reportText()));
        QCOMPARE(restored.size(), 1);
        // One safety-backup naming for the GUI and the CLI: next to the image.
        QVERIFY2(restore->progressPage()->reportText().contains(image + QStringLiteral(".safety-")),
                 qPrintable(restore->progressPage()->reportText()));
    }
    restore->close();
}

void ReportAndCountsTest::noHeadingStandsAloneAtAPageFoot() {
    // Issue 12, point 8: a heading at a page's end, its table on the next.
    QString html;
    for (int section = 0; section < 12; ++section) {
        html += QStringLiteral("<h2>Section %1</h2>").arg(section);
        for (int line = 0; line < 3 + section % 5; ++line)
            html += QStringLiteral("<p>Line %1 of section %2</p>").arg(line).arg(section);
    }
    QTextDocument document;
    document.setHtml(html);
    const qreal pageHeight = 300;
    document.setPageSize(QSizeF(400, pageHeight));
    QVERIFY(keepHeadingsWithText(document) > 0);
    for (QTextBlock block = document.begin(); block.isValid(); block = block.next()) {
        if (block.blockFormat().headingLevel() == 0) continue;
        const qreal top = document.documentLayout()->blockBoundingRect(block).top();
        const qreal onPage = top - std::floor(top / pageHeight) * pageHeight;
        QVERIFY2(onPage < pageHeight * 0.8, qPrintable(block.text()));
    }
}

void ReportAndCountsTest::reportMinimumCycleTimeIsInMilliseconds() {
    // "Minimum cycle time 0 0.1 ms" was printed; the value is in 0.1 ms steps.
    for (const SettingSpec& spec : settingSpecs()) {
        if (qstrcmp(spec.key, "targetCycleTime") != 0) continue;
        QCOMPARE(SettingField::textWithUnit(spec, 125), QStringLiteral("12.5 ms"));
        QCOMPARE(SettingField::textWithUnit(spec, 0), QStringLiteral("0.0 ms"));
        return;
    }
    QFAIL("no setting targetCycleTime");
}

void ReportAndCountsTest::reportShowsOnlyValuesOfTheConnectedDevice() {
    // Issue 28, point 2: a 3964R device's dead-time modes read, then a
    // Cam-BUS device on the line: its report shows no device value of the
    // first, and says the section was not read from this device.
    auto shell = startOnSimulator(QStringLiteral("sim:throttle=0"), QStringLiteral("3964r-n96"));
    QVERIFY(shell);
    Workspace* workspace = camConWorkspace(*shell);
    QSignalSpy done(camConWindow(shell->window()), &CamConWindow::everythingRead);
    camConWindow(shell->window())->readEverything(0);
    QVERIFY(done.wait(kDeviceTimeoutMs));
    QTRY_VERIFY_WITH_TIMEOUT(!workspace->deadTimeModes().device().isEmpty(), kDeviceTimeoutMs);
    const OutputDeadTime first = workspace->deadTimeMode(1).value_or(OutputDeadTime{});
    OutputDeadTime edited = first;
    edited.on += 10;  // the mode's own word (word 0 is the Dead times section's)
    workspace->editDeadTimeMode(1, edited);
    QVERIFY(reportText(*workspace).contains(QStringLiteral("(device: ")));

    const comm::ProtocolInfo* cambus =
        comm::ProtocolRegistry::instance().find(QStringLiteral("cambus"));
    QVERIFY(cambus);
    comm::ConnectionSettings connection = shell->session()->connection();
    connection.protocol = cambus->id;
    connection.serial = cambus->defaultSerial;
    shell->session()->connectTo(connection, comm::ProtocolSettingsPtr(cambus->makeSettings()));
    QTRY_VERIFY_WITH_TIMEOUT(shell->session()->isOnline() && shell->session()->deviceChecked(),
                             kDeviceTimeoutMs);
    QVERIFY(workspace->deadTimeModes().device().isEmpty());
    const QString text = reportText(*workspace);
    const QString section = text.section(QStringLiteral("Dead-time modes"), 1);
    QVERIFY2(!section.isEmpty(), qPrintable(text));
    QCOMPARE(section.count(QStringLiteral("(device: ")),
             section.count(QStringLiteral("(device: not read from this device)")));
    // The edit stays, said as not read from this device.
    QVERIFY2(text.contains(QStringLiteral("not read from this device")), qPrintable(text));
}

QTEST_MAIN(ReportAndCountsTest)
#include "tst_report_and_counts.moc"
