// Issue 37, item 4: Machine → History… with real widgets, a CamCon and an
// MC200 each on its own in-process simulated device. Two versions are
// stored (the second after a variable and a volatile counter of the MC200
// changed); the dialog lists both with what changed in each, compares the
// two device by device (the counter left out), compares the first with
// the devices now, and marks the first released - a tag that plain git
// and the archive read back. Then the CamCon's programs changed between
// two versions are drawn (the CamCon's FamilyGui::backupDrawing), one
// program at a time, the MC200 keeping its table; and those changed since
// a version on the device, compared with the devices now (each backed up
// into a temporary folder, as `machine watch` does).
#include "history_fixture.h"
#include "shell_fixture.h"

#include "comm/camcon/camcon_device.h"
#include "comm/device/device_connection.h"
#include "comm/mc1/mc1_device.h"
#include "comm/usecases/machine_backup.h"
#include "comm/usecases/machine_history.h"
#include "model/atomic_file.h"
#include "model/machine/machine_archive.h"
#include "model/machine/machine_backup_folder.h"
#include "model/machine/machine_file.h"
#include "ui/camcon/backup_programs_view.h"
#include "ui/camcon/program_diff_view.h"
#include "ui/device_session.h"
#include "ui/dialog_stop.h"
#include "ui/machine/machine.h"
#include "ui/machine/machine_history_dialog.h"
#include "ui/machine/machine_progress.h"
#include "ui/machine/machine_report.h"
#include "ui/machine/machine_report_changes.h"
#include "ui/machine/machine_unit.h"
#include "ui/machine/machine_window.h"

#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QRegularExpression>
#include <QScreen>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTextDocument>
#include <QTreeWidget>

#include <memory>
#include <optional>

using namespace cambench;
using namespace cambench::test;

namespace {

// A CamCon and an MC200 V2 whose V100-V199 are counters.
MachineFile press() {
    MachineFile file;
    file.machine = QStringLiteral("History press");
    file.devices << MachineDevice{QStringLiteral("cams"),
                                  QStringLiteral("camcon"),
                                  {{QStringLiteral("port"), QStringLiteral("sim:throttle=0")},
                                   {QStringLiteral("protocol"), QStringLiteral("standard")}},
                                  {},
                                  {}}
                 << MachineDevice{QStringLiteral("press-plc"),
                                  QStringLiteral("mc1"),
                                  {{QStringLiteral("port"), QStringLiteral("sim:variant=mc200v2")},
                                   {QStringLiteral("protocol"), QStringLiteral("mc1")},
                                   {QStringLiteral("variant"), QStringLiteral("mc200v2")}},
                                  {},
                                  {QStringLiteral("V100-V199")}};
    return file;
}

bool writeVariable(MachineUnit* plc, int number, qint64 value) {
    const auto written =
        runOn<comm::Mc1Device, Done>(plc, [=](comm::Mc1Device& device, comm::JobContext&) {
            return device.writeVariable(number, value);
        });
    return written && *written;
}

bool writeCams(MachineUnit* cams, int program, const Track& track) {
    const auto written =
        runOn<comm::CamConDevice, Done>(cams, [=](comm::CamConDevice& device, comm::JobContext&) {
            return device.writeTrack(program, track);
        });
    return written && *written;
}

QStringList textsOf(const QListWidget* list) {
    QStringList texts;
    for (int row = 0; row < list->count(); ++row) texts << list->item(row)->text();
    return texts;
}

// A machine of simulated devices, connected, whose CamCon holds `cams`
// (program, track) and whose archive holds a first version of it
// ("commissioning"), as the tests below start.
struct Archived {
    Shell shell;
    Machine* machine = nullptr;
    MachineUnit* cams = nullptr;
    QTemporaryDir work;
    std::optional<MachineArchive> archive;
    QString first;  // the first version's id
};

std::unique_ptr<Archived> archived(const MachineFile& file, const QList<QPair<int, Track>>& cams) {
    auto made = std::make_unique<Archived>();
    made->machine = made->shell.openMachine(file, {});
    if (!waitConnected(*made->machine)) return {};
    made->cams = made->machine->unit(QStringLiteral("cams"));
    for (const auto& [program, track] : cams)
        if (!writeCams(made->cams, program, track)) return {};
    Result<MachineArchive> archive =
        MachineArchive::openOrCreate(made->work.filePath(QStringLiteral("archive")));
    if (!archive) return {};
    made->archive = std::move(archive).value();
    const Result<usecases::VersionStored> first =
        storeVersion(made->machine, *made->archive, QStringLiteral("commissioning"));
    if (!first || !first->stored) return {};
    made->first = first->id;
    return made;
}

}  // namespace

class TestMachineHistory : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { useTestSettings(); }

    void versionsComparedAndReleased() {
        Shell shell;
        Machine* machine = shell.openMachine(press(), {});
        QVERIFY(waitConnected(*machine));
        MachineUnit* plc = machine->unit(QStringLiteral("press-plc"));
        // Connected, the device's line is rebuilt from its connection: the
        // items that change by themselves stay the file's.
        QCOMPARE(machine->file().devices.at(1).volatileItems, QStringList{"V100-V199"});
        QTemporaryDir work;
        const Result<MachineArchive> archive =
            MachineArchive::openOrCreate(work.filePath(QStringLiteral("archive")));
        QVERIFY(archive.ok());

        const Result<usecases::VersionStored> first =
            storeVersion(machine, *archive, QStringLiteral("commissioning"));
        QVERIFY2(first.ok() && first->stored, qPrintable(first.error().message));
        QVERIFY(writeVariable(plc, 12, 4711));
        QVERIFY(writeVariable(plc, 150, 99));  // a counter: never a difference
        const Result<usecases::VersionStored> second =
            storeVersion(machine, *archive, QStringLiteral("new stroke"));
        QVERIFY2(second.ok() && second->stored, qPrintable(second.error().message));

        MachineHistoryDialog dialog(machine, archive->dir());
        dialog.show();
        // Within the screen, its buttons included (it was 760 high: on a
        // laptop's 768 pixels its buttons were below the edge).
        QVERIFY(dialog.frameGeometry().height() <= dialog.screen()->availableGeometry().height());
        QTreeWidget* list = dialog.versionList();
        QCOMPARE(list->topLevelItemCount(), 2);
        QTreeWidgetItem* newest = list->topLevelItem(0);
        QCOMPARE(newest->text(MachineHistoryDialog::Version), second->id.left(10));
        QCOMPARE(newest->text(MachineHistoryDialog::Note), QStringLiteral("new stroke"));
        QCOMPARE(newest->text(MachineHistoryDialog::Author), QStringLiteral("tester"));
        QCOMPARE(newest->childCount(), 1);  // only the MC200 changed
        QCOMPARE(newest->child(0)->text(MachineHistoryDialog::Note),
                 QStringLiteral("press-plc: V12 0 → 4711"));
        QVERIFY(list->topLevelItem(1)->childCount() == 2);  // the first: every device

        // The two compared: the MC200's V12, nothing of the CamCon, the counter left out.
        selectVersions(list, {0, 1});
        QVERIFY(dialog.compareButton()->isEnabled());
        QVERIFY(!dialog.restoreButton()->isEnabled());
        dialog.compareButton()->click();
        const QStringList rows = rowsOf(dialog.differenceTable());
        QVERIFY2(rows.contains(QStringLiteral("cams||||equal")), qPrintable(rows.join(u'\n')));
        QVERIFY2(rows.contains(QStringLiteral("press-plc|V12|0|4711|V12 0 → 4711")),
                 qPrintable(rows.join(u'\n')));
        QCOMPARE(rows.size(), 2);
        QVERIFY2(dialog.statusLabel()->text().contains(QLatin1String("differences in "
                                                                     "press-plc")),
                 qPrintable(dialog.statusLabel()->text()));

        // The first against the devices now: the MC200 differs, read from the device.
        selectVersions(list, {1});
        QSignalSpy finished(&dialog, &MachineHistoryDialog::finished);
        dialog.compareNowButton()->click();
        QVERIFY(finished.wait(kDeviceTimeoutMs));
        const QStringList now = rowsOf(dialog.differenceTable());
        QVERIFY2(now.contains(QStringLiteral("press-plc|V12|0|4711|V12 0 → 4711")),
                 qPrintable(now.join(u'\n')));
        QVERIFY2(now.contains(QStringLiteral("cams||||equal")), qPrintable(now.join(u'\n')));

        // Marked released: the first is the one that should be on the machine.
        selectVersions(list, {1});
        dialog.releaseButton()->click();
        QCOMPARE(*archive->released(), first->id);
        QCOMPARE(list->topLevelItem(1)->text(MachineHistoryDialog::Released),
                 QStringLiteral("released, released-1"));
        QCOMPARE(list->topLevelItem(0)->text(MachineHistoryDialog::Released), QString());
    }

    // Two CamCon programs changed between the versions (and the MC200's
    // V12): the CamCon's row offers the drawing of exactly those programs,
    // their changed cams listed as Compare programs words them; the MC200
    // has its table only. A program changed on the device since the
    // newer version: compared with the devices now, exactly that program
    // and output is drawn, from the backup just read, which is removed.
    void camProgramsDrawn() {
        const std::unique_ptr<Archived> open =
            archived(press(), {{0, Track{1, {{10, 20}}}}, {3, Track{5, {{100, 200}}}}});
        QVERIFY(open);
        Machine* machine = open->machine;
        MachineUnit* cams = open->cams;
        const MachineArchive* archive = &*open->archive;
        // Program 0: output 1's cam made longer, a cam added on output 4;
        // program 3: output 5's cam taken away.
        QVERIFY(writeCams(cams, 0, Track{1, {{10, 40}}}));
        QVERIFY(writeCams(cams, 0, Track{4, {{300, 330}}}));
        QVERIFY(writeCams(cams, 3, Track{5, {}}));
        QVERIFY(writeVariable(machine->unit(QStringLiteral("press-plc")), 12, 4711));
        const Result<usecases::VersionStored> second =
            storeVersion(machine, *archive, QStringLiteral("longer glue"));
        QVERIFY2(second.ok() && second->stored, qPrintable(second.error().message));

        MachineHistoryDialog dialog(machine, archive->dir());
        dialog.show();
        selectVersions(dialog.versionList(), {0, 1});
        dialog.compareButton()->click();
        const QStringList rows = rowsOf(dialog.differenceTable());
        QVERIFY2(rows.contains(QStringLiteral("press-plc|V12|0|4711|V12 0 → 4711")),
                 qPrintable(rows.join(u'\n')));
        QVERIFY2(dialog.statusLabel()->text().contains(QLatin1String("Drawn as well: cams")),
                 qPrintable(dialog.statusLabel()->text()));
        QVERIFY(dialog.drawingOf(QStringLiteral("cams")));
        QVERIFY(!dialog.drawingOf(QStringLiteral("press-plc")));  // a table is all

        // The MC200's row: nothing to draw; the CamCon's: its drawing.
        QTableWidget* table = dialog.differenceTable();
        const auto rowOf = [table](const QString& device) {
            for (int row = 0; row < table->rowCount(); ++row)
                if (table->item(row, MachineHistoryDialog::Device)->text() == device) return row;
            return -1;
        };
        table->setCurrentCell(rowOf(QStringLiteral("press-plc")), 0);
        QVERIFY(!dialog.drawButton()->isEnabled());
        table->setCurrentCell(rowOf(QStringLiteral("cams")), 0);
        QVERIFY(dialog.drawButton()->isEnabled());
        dialog.drawButton()->click();
        QDialog* drawing = dialog.drawingOf(QStringLiteral("cams"));
        QVERIFY(QTest::qWaitForWindowExposed(drawing));
        QVERIFY2(drawing->windowTitle().contains(open->first.left(10)) &&
                     drawing->windowTitle().contains(second->id.left(10)),
                 qPrintable(drawing->windowTitle()));
        // The MC200 can move: the drawing has its STOP, as every dialog.
        QVERIFY(DialogStop::of(drawing));

        auto* view = drawing->findChild<BackupProgramsView*>();
        QVERIFY(view);
        QCOMPARE(view->programs(), (QList<int>{0, 3}));
        QCOMPARE(view->programChoice()->count(), 2);
        QCOMPARE(view->shownProgram(), 0);
        QCOMPARE(textsOf(view->differenceList()),
                 (QStringList{QStringLiteral("output 1, cam 1: 10..20 → 10..40"),
                              QStringLiteral("output 4: cam 300..330 only in B")}));
        // Only the outputs that differ are drawn (the others fold away).
        QCOMPARE(view->view()->shownOutputs(), (QList<int>{1, 4}));
        QVERIFY2(view->summary().contains(
                     QStringLiteral("A: version %1, program 0").arg(open->first.left(10))) &&
                     view->summary().contains(
                         QStringLiteral("B: version %1, program 0").arg(second->id.left(10))),
                 qPrintable(view->summary()));
        // A line of the list selects its cams in the drawing.
        view->differenceList()->setCurrentRow(1);
        QCOMPARE(view->view()->selected(), 1);

        view->showProgram(3);
        QCOMPARE(textsOf(view->differenceList()),
                 QStringList{QStringLiteral("output 5: cam 100..200 only in A")});
        QCOMPARE(view->view()->shownOutputs(), QList<int>{5});

        // The second against the devices now, after program 3's output 6
        // got a cam on the device: that program and output drawn, from the
        // backup just read (program 0 is the same as in the version).
        QVERIFY(writeCams(cams, 3, Track{6, {{50, 70}}}));
        selectVersions(dialog.versionList(), {0});
        QSignalSpy finished(&dialog, &MachineHistoryDialog::finished);
        QTemporaryDir temporary;
        const bool tmpWasSet = qEnvironmentVariableIsSet("TMPDIR");
        const QByteArray tmpBefore = qgetenv("TMPDIR");
        qputenv("TMPDIR", QFile::encodeName(temporary.path()));
        dialog.compareNowButton()->click();
        const bool answered = finished.wait(kDeviceTimeoutMs);
        if (tmpWasSet)
            qputenv("TMPDIR", tmpBefore);
        else
            qunsetenv("TMPDIR");
        QVERIFY(answered);
        const QStringList now = rowsOf(dialog.differenceTable());
        QCOMPARE(now, (QStringList{QStringLiteral("cams|program 3, output 6 cam||50–70|"
                                                  "program 3, output 6: cam 50–70 added"),
                                   QStringLiteral("press-plc||||equal")}));
        QVERIFY2(dialog.statusLabel()->text().contains(QLatin1String("Drawn as well: cams")),
                 qPrintable(dialog.statusLabel()->text()));
        QVERIFY(!dialog.drawingOf(QStringLiteral("press-plc")));
        table->setCurrentCell(rowOf(QStringLiteral("cams")), 0);
        QVERIFY(dialog.drawButton()->isEnabled());
        dialog.drawButton()->click();
        QDialog* drawnNow = dialog.drawingOf(QStringLiteral("cams"));
        QVERIFY(QTest::qWaitForWindowExposed(drawnNow));
        QCOMPARE(drawnNow->windowTitle(),
                 QStringLiteral("cams: version %1 → the devices now").arg(second->id.left(10)));
        auto* viewNow = drawnNow->findChild<BackupProgramsView*>();
        QVERIFY(viewNow);
        QCOMPARE(viewNow->programs(), QList<int>{3});
        QCOMPARE(textsOf(viewNow->differenceList()),
                 QStringList{QStringLiteral("output 6: cam 50..70 only in B")});
        QCOMPARE(viewNow->view()->shownOutputs(), QList<int>{6});
        QVERIFY2(viewNow->summary().contains(QLatin1String("B: the devices now, program 3")),
                 qPrintable(viewNow->summary()));
        // The backup read for it is removed: of the temporary folders only
        // the version's is left, which the dialog keeps for its devices' jobs.
        QCOMPARE(QDir(temporary.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot).size(),
                 1);
    }

    // Machine report with the changes since the released version: the
    // devices changed since are listed with their differences, a device not
    // on the line is "NOT COMPARED" (never "equal"); without a released
    // version or an archive, the section says so.
    void reportSaysChangesSinceRelease() {
        MachineFile file = press();
        file.devices << MachineDevice{QStringLiteral("feed"),
                                      QStringLiteral("compax3"),
                                      {{QStringLiteral("port"), QStringLiteral("sim")}},
                                      {},
                                      {}};
        const std::unique_ptr<Archived> open = archived(file, {{0, Track{1, {{10, 20}}}}});
        QVERIFY(open);
        Machine* machine = open->machine;
        MachineUnit* cams = open->cams;
        const MachineArchive* archive = &*open->archive;

        const auto sectionText = [](Machine* machine, const QString& archiveDir) {
            std::optional<ReleasedChanges> said;
            QObject context;
            MachineReportChanges::compare(machine, archiveDir, &context,
                                          [&said](ReleasedChanges changes) { said = changes; });
            if (!QTest::qWaitFor([&said] { return said.has_value(); }, kDeviceTimeoutMs))
                return QStringLiteral("(no answer)");
            QTextDocument document;
            MachineReport::build(document, *machine, &*said);
            return document.toPlainText();
        };
        // Nothing released yet: said, nothing compared.
        const QString unreleased = sectionText(machine, archive->dir());
        QVERIFY2(unreleased.contains(QLatin1String("Nothing was compared: No version of")) &&
                     !unreleased.contains(QLatin1String("equal to the released version")),
                 qPrintable(unreleased));
        QVERIFY(archive->release(open->first, QStringLiteral("tester"), {}).ok());

        QVERIFY(writeCams(cams, 0, Track{1, {{10, 40}}}));
        QVERIFY(writeVariable(machine->unit(QStringLiteral("press-plc")), 12, 4711));
        MachineUnit* feed = machine->unit(QStringLiteral("feed"));
        // A Compax3's motion cannot be told: the question before leaving it.
        const auto leave = answerLeaveQuestion();
        QVERIFY(feed->session()->disconnectFromDevice());
        QVERIFY(QTest::qWaitFor([feed] { return !feed->session()->isOnline(); }, kDeviceTimeoutMs));

        const QString text = sectionText(machine, archive->dir());
        QVERIFY2(text.contains(QLatin1String("Changes since the released version")),
                 qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("Released version: released-1: version %1")
                                   .arg(open->first.left(10))),
                 qPrintable(text));
        static const QRegularExpression camsDiffer(QStringLiteral(
            "cams\\s+DIFFERS: 1 difference\\(s\\)\\s+program 0, output 1: cam 10–20 → 10–40"));
        QVERIFY2(camsDiffer.match(text).hasMatch(), qPrintable(text));
        static const QRegularExpression plcDiffers(
            QStringLiteral("press-plc\\s+DIFFERS: 1 difference\\(s\\)\\s+V12 0 → 4711"));
        QVERIFY2(plcDiffers.match(text).hasMatch(), qPrintable(text));
        static const QRegularExpression feedNotCompared(
            QStringLiteral("feed\\s+NOT COMPARED: \\S"));
        QVERIFY2(feedNotCompared.match(text).hasMatch(), qPrintable(text));
        QVERIFY2(!text.contains(QLatin1String("equal to the released version")), qPrintable(text));

        // Through the window: the PDF is written after the comparison, and
        // each device's line says its read and its comparison.
        const QString pdf = open->work.filePath(QStringLiteral("press.pdf"));
        MachineProgress* progress = machine->window()->writeReportTo(pdf, archive->dir());
        QVERIFY(QTest::qWaitFor([&] { return QFile::exists(pdf); }, 4 * kDeviceTimeoutMs));
        QVERIFY2(progress->resultLine(QStringLiteral("cams"))
                     .startsWith(QLatin1String("read; DIFFERS: 1 difference(s)")),
                 qPrintable(progress->resultLine(QStringLiteral("cams"))));
        QVERIFY2(progress->resultLine(QStringLiteral("press-plc"))
                     .startsWith(QLatin1String("read; DIFFERS")),
                 qPrintable(progress->resultLine(QStringLiteral("press-plc"))));
        QVERIFY2(
            progress->resultLine(QStringLiteral("feed")).startsWith(QLatin1String("not read")) &&
                progress->resultLine(QStringLiteral("feed"))
                    .contains(QLatin1String("NOT COMPARED")),
            qPrintable(progress->resultLine(QStringLiteral("feed"))));

        // A machine without the feed: the released version's feed is said,
        // not left out.
        Machine* smaller = open->shell.openMachine(press(), {});
        QVERIFY(waitConnected(*smaller));
        const QString withoutFeed = sectionText(smaller, archive->dir());
        static const QRegularExpression feedGone(QStringLiteral(
            "feed\\s+in the released version, but no longer a device of this machine"));
        QVERIFY2(feedGone.match(withoutFeed).hasMatch(), qPrintable(withoutFeed));

        // No archive chosen: the report says the section is not part of it.
        QTextDocument without;
        const ReleasedChanges none;
        MachineReport::build(without, *machine, &none);
        QVERIFY(without.toPlainText().contains(
            QLatin1String("Not part of this report: no machine archive was chosen.")));
    }

    // Restore this version: each device's plan is listed before anything
    // is written (the identity checked first), and after the restore every
    // device equals that version again.
    void restoreThisVersion() {
        const std::unique_ptr<Archived> open = archived(press(), {{0, Track{1, {{10, 20}}}}});
        QVERIFY(open);
        Machine* machine = open->machine;
        MachineUnit* cams = open->cams;
        const MachineArchive* archive = &*open->archive;
        QVERIFY(writeCams(cams, 0, Track{1, {{10, 40}}}));
        QVERIFY(writeVariable(machine->unit(QStringLiteral("press-plc")), 12, 4711));

        MachineHistoryDialog dialog(machine, archive->dir());
        dialog.show();
        selectVersions(dialog.versionList(), {0});
        QString details;
        NextDialog<QMessageBox> answer([&details](QMessageBox* box) {
            if (box->objectName() != QLatin1String("restoreVersionQuestion")) return;
            details = box->detailedText();
            box->button(QMessageBox::Yes)->click();
        });
        QSignalSpy finished(&dialog, &MachineHistoryDialog::finished);
        dialog.restoreButton()->click();
        QVERIFY(finished.wait(4 * kDeviceTimeoutMs));
        QCOMPARE(answer.answered(), 1);
        // The plan: what each device will change, read from it.
        QVERIFY2(details.contains(QLatin1String("cams: 1 item(s) to change")) &&
                     details.contains(QLatin1String("program 0, output 1")) &&
                     details.contains(QLatin1String("press-plc: 1 item(s) to change")) &&
                     details.contains(QStringLiteral("V12 4711 → 0")),
                 qPrintable(details));
        QVERIFY2(dialog.statusLabel()->text().contains(QLatin1String("cams: restored")) &&
                     dialog.statusLabel()->text().contains(QLatin1String("press-plc: restored")),
                 qPrintable(dialog.statusLabel()->text()));

        // The devices now equal the version.
        QVERIFY(QTest::qWaitFor([&] { return dialog.compareNowButton()->isEnabled(); },
                                kDeviceTimeoutMs));
        dialog.compareNowButton()->click();
        QVERIFY(finished.wait(4 * kDeviceTimeoutMs));
        const QStringList rows = rowsOf(dialog.differenceTable());
        QCOMPARE(rows, (QStringList{QStringLiteral("cams||||equal"),
                                    QStringLiteral("press-plc||||equal")}));
    }
};

QTEST_MAIN(TestMachineHistory)
#include "tst_machine_history.moc"
