// Issue 12, points 2 and 7: edits on the table interface's own pages
// (dead-time modes, analogue cams, programming program, EEPROM lock) are
// marked as edited, counted in the title and asked about before quitting,
// listed in Compare with device and written through the one write path; a
// value the device would refuse is refused before anything is sent, saying
// what and where; values never read say so; a project carries them.
#include "camcon_fixture.h"

#include "model/camcon/project_file.h"
#include "ui/camcon/analogue_cams_page.h"
#include "ui/camcon/commissioning_report.h"
#include "ui/camcon/compare_dialog.h"
#include "ui/camcon/dead_time_modes_page.h"
#include "ui/camcon/dead_times_model.h"
#include "ui/camcon/dead_times_page.h"
#include "ui/camcon/eeprom_lock_page.h"
#include "ui/camcon/programming_program_page.h"
#include "ui/camcon/workspace.h"
#include "ui/change_marker.h"
#include "ui/language.h"
#include "ui/report_dialog.h"

#include <QAbstractButton>
#include <QComboBox>
#include <QLabel>
#include <QMessageBox>
#include <QSpinBox>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTextDocument>
#include <QTreeWidget>
#include <QtTest>

using namespace cambench;
using namespace cambench::test;

namespace {

std::unique_ptr<Shell> startOnTable() {
    return startOnSimulator(QStringLiteral("sim:throttle=0"), QStringLiteral("3964r-n96"));
}

// Quits, reads the question's texts and cancels it; true when it asked.
bool quitAsks(MainWindow* window, QString* question) {
    NextDialog<QMessageBox> cancel([question](QMessageBox* box) {
        *question = box->text() + QLatin1Char('\n') + box->informativeText();
        box->button(QMessageBox::Cancel)->click();
    });
    const bool closed = window->confirmClose();
    return !closed && cancel.answered() == 1;
}

}  // namespace

class TablePageEditsTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        useTestSettings();
        QVERIFY(setLanguage(QStringLiteral("en")));
    }
    void deadTimeModeEditIsMarkedCountedAndAskedAbout();
    void analogueEditIsCountedAndARefusalSaysWhere();
    void programmingProgramEditIsMarkedAndCounted();
    void projectFileCarriesDeadTimeModesThroughThePage();
    void aDeadTimeIsOneValueOnBothPages();
    void projectFileKeepsTheAnalogueCams();
    void compareListsAndWritesTheTableSections();
    void settingsOfAnotherProtocolAreNoEdits();
};

void TablePageEditsTest::deadTimeModeEditIsMarkedCountedAndAskedAbout() {
    auto shell = startOnTable();
    QVERIFY(shell);
    auto* modes = shell->window()->findChild<DeadTimeModesPage*>();
    QTRY_VERIFY_WITH_TIMEOUT(modes->onDevice().size() == 32, kDeviceTimeoutMs);
    const int before = camConWorkspace(*shell)->changedCount();

    // Output 5's switch-on dead time typed as 3.5 ms, as the delegate commits it.
    QTableWidget* table = modes->table();
    QTableWidgetItem* on = table->item(4, DeadTimeModesPage::OnColumn);
    on->setData(Qt::EditRole, 3.5);
    QCOMPARE(camConWorkspace(*shell)->changedCount(), before + 1);
    QVERIFY(on->font().bold());
    QVERIFY2(on->toolTip().startsWith(QLatin1String("On the device: ")), qPrintable(on->toolTip()));
    QVERIFY(table->item(4, DeadTimeModesPage::OutputColumn)->text().startsWith(changedMarker()));
    QVERIFY(!table->item(3, DeadTimeModesPage::OnColumn)->font().bold());
    QVERIFY2(shell->window()->windowTitle().contains(QLatin1String("not written")),
             qPrintable(shell->window()->windowTitle()));

    QString question;
    QVERIFY(quitAsks(shell->window(), &question));
    QVERIFY2(question.contains(QString::number(before + 1)), qPrintable(question));
    QCOMPARE(modes->differences().size(), 1);
    QCOMPARE(modes->differences().first().item, WorkspaceItem::deadTimeMode(5));

    // Written through the one write path: the mark and the count go.
    std::optional<WriteResult> result;
    modes->writeChanges([&](const WriteResult& r) { result = r; });
    QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), kDeviceTimeoutMs);
    QVERIFY2(result->ok() && (*result)->complete(), qPrintable(writeDetails(*result)));
    QCOMPARE((*result)->deadTimeModes.size(), 1);
    QCOMPARE(camConWorkspace(*shell)->changedCount(), before);
    QVERIFY(!table->item(4, DeadTimeModesPage::OnColumn)->font().bold());
}

void TablePageEditsTest::analogueEditIsCountedAndARefusalSaysWhere() {
    auto shell = startOnTable();
    QVERIFY(shell);
    auto* analogue = shell->window()->findChild<AnalogueCamsPage*>();
    QTRY_COMPARE_WITH_TIMEOUT(analogue->onDevice().points.size(), 3, kDeviceTimeoutMs);
    const int before = camConWorkspace(*shell)->changedCount();
    // The second point's position set below the first's: out of order.
    QTableWidgetItem* position = analogue->table()->item(1, 0);
    position->setData(Qt::EditRole, -5);
    QCOMPARE(camConWorkspace(*shell)->changedCount(), before + 1);
    QVERIFY(position->font().bold());

    // Said on the page before anything is written, naming the point.
    bool problemShown = false;
    for (QLabel* label : analogue->findChildren<QLabel*>())
        problemShown |= label->text().contains(QLatin1String("base point 2"));
    QVERIFY(problemShown);

    // The write is refused before anything is sent, saying what and where.
    QString seen;
    NextDialog<ReportDialog> close([&seen](ReportDialog* dialog) {
        seen = dialog->summary() + QLatin1Char('\n') + dialog->details();
        dialog->accept();
    });
    std::optional<WriteResult> result;
    analogue->writeChanges([&](const WriteResult& r) { result = r; });
    QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), kDeviceTimeoutMs);
    QVERIFY(!result->ok());
    QVERIFY2(result->error().message.contains(QLatin1String("Analogue output 1, base point 2")),
             qPrintable(result->error().message));
    QVERIFY2(seen.contains(QLatin1String("base point 2")), qPrintable(seen));
    QVERIFY2(!seen.contains(QLatin1String("reply may have been lost")), qPrintable(seen));
    // The edit stays, counted.
    QCOMPARE(camConWorkspace(*shell)->changedCount(), before + 1);
    QString question;
    QVERIFY(quitAsks(shell->window(), &question));
    QVERIFY2(question.contains(QString::number(before + 1)), qPrintable(question));
}

void TablePageEditsTest::programmingProgramEditIsMarkedAndCounted() {
    auto shell = startOnTable();
    QVERIFY(shell);
    auto* page = shell->window()->findChild<ProgrammingProgramPage*>();
    QLabel* state = nullptr;
    for (QLabel* label : page->findChildren<QLabel*>())
        if (label->text().startsWith(QLatin1String("As on the device")) ||
            label->text().startsWith(QLatin1String("Not read")))
            state = label;
    QVERIFY(state);
    QTRY_COMPARE_WITH_TIMEOUT(state->text(), QStringLiteral("As on the device."), kDeviceTimeoutMs);
    const int before = camConWorkspace(*shell)->changedCount();
    auto* program = page->findChildren<QSpinBox*>().first();
    program->setValue(program->value() + 1);
    QCOMPARE(camConWorkspace(*shell)->changedCount(), before + 1);
    QVERIFY(program->font().bold());
    QVERIFY2(state->text().contains(QLatin1String("Edited, not written")),
             qPrintable(state->text()));
}

void TablePageEditsTest::projectFileCarriesDeadTimeModesThroughThePage() {
    // Issue 12, point 2: a project's dead-time modes are edits on the page
    // (marked, counted, written there) and a project saved again keeps them.
    auto shell = startOnTable();
    QVERIFY(shell);
    auto* modes = shell->window()->findChild<DeadTimeModesPage*>();
    QTRY_VERIFY_WITH_TIMEOUT(modes->onDevice().size() == 32, kDeviceTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(!camConWindow(shell->window())->isReadingDevice(), kDeviceTimeoutMs);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.json"));
    QVERIFY(camConWindow(shell->window())->saveProjectTo(path).ok());
    Result<Project> saved = loadProject(path);
    QVERIFY2(saved.ok(), qPrintable(saved.error().message));
    QCOMPARE(saved->deadTimeModes, modes->onDevice());
    QVERIFY(saved->readAt.parts.contains(ProjectPart::DeadTimeModes) ||
            saved->deadTimeModes == modes->onDevice());

    Project edited = *saved;
    const OutputDeadTime wanted{DeadTimeMode::PathTime, 0, 20, 300};
    edited.deadTimeModes.insert(6, wanted);
    edited.readAt = {};
    QVERIFY(saveProject(path, edited).ok());
    const int before = camConWorkspace(*shell)->changedCount();
    const auto keep = answerReplaceEdits(false);
    camConWindow(shell->window())->openProjectFile(path);
    QCOMPARE(modes->edited(6), wanted);
    QVERIFY(modes->table()
                ->item(5, DeadTimeModesPage::OutputColumn)
                ->text()
                .startsWith(changedMarker()));
    QVERIFY(camConWorkspace(*shell)->changedCount() >= before + 1);

    // The report prints them, the edited one marked with the device's value.
    QTextDocument report;
    CommissioningReport::build(report, *camConWorkspace(*shell));
    const QString text = report.toPlainText();
    QVERIFY2(text.contains(QLatin1String("Dead-time modes")), qPrintable(text));
    QVERIFY2(text.contains(changedMarker() + QLatin1String("Path-time (device: Normal)")),
             qPrintable(text));

    const QString again = dir.filePath(QStringLiteral("again.json"));
    QVERIFY(camConWindow(shell->window())->saveProjectTo(again).ok());
    const Result<Project> reloaded = loadProject(again);
    QVERIFY2(reloaded.ok(), qPrintable(reloaded.error().message));
    QCOMPARE(reloaded->deadTimeModes.value(6), wanted);
    QVERIFY(!reloaded->readAt.parts.contains(ProjectPart::DeadTimeModes));
}

void TablePageEditsTest::aDeadTimeIsOneValueOnBothPages() {
    // Issue 38, item 3: word 0 of a dead-time mode is the plain dead time of
    // the Dead times page; typed on either page it is one edit, shown on
    // both, and one write settles both.
    auto shell = startOnTable();
    QVERIFY(shell);
    auto* modes = shell->window()->findChild<DeadTimeModesPage*>();
    auto* plain = shell->window()->findChild<DeadTimesPage*>();
    QVERIFY(plain);
    QTRY_VERIFY_WITH_TIMEOUT(modes->onDevice().size() == 32, kDeviceTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(!camConWindow(shell->window())->isReadingDevice(), kDeviceTimeoutMs);
    const int before = camConWorkspace(*shell)->changedCount();
    DeadTimesModel* model = plain->model();
    const auto shownPlain = [model](int output) {
        return model->data(model->index(output - 1, DeadTimesModel::DeadTimeColumn), Qt::EditRole)
            .toDouble();
    };

    // Output 3's dead time typed on the Dead-time modes page as 4.5 ms.
    QTableWidgetItem* normal = modes->table()->item(2, DeadTimeModesPage::NormalColumn);
    normal->setData(Qt::EditRole, 4.5);
    QCOMPARE(shownPlain(3), 4.5);
    QVERIFY(model->isChanged(3));
    QCOMPARE(camConWorkspace(*shell)->changedCount(), before + 1);
    // Output 4's typed on the Dead times page as 6 ms: the modes page shows it, marked.
    QVERIFY(model->setData(model->index(3, DeadTimesModel::DeadTimeColumn), 6.0));
    QCOMPARE(
        modes->table()->item(3, DeadTimeModesPage::NormalColumn)->data(Qt::EditRole).toDouble(),
        6.0);
    QVERIFY(modes->table()->item(3, DeadTimeModesPage::NormalColumn)->font().bold());
    QCOMPARE(camConWorkspace(*shell)->changedCount(), before + 2);
    // A project saved now does not call the modes read from the device.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.json"));
    QVERIFY(camConWindow(shell->window())->saveProjectTo(path).ok());
    const Result<Project> saved = loadProject(path);
    QVERIFY2(saved.ok(), qPrintable(saved.error().message));
    QCOMPARE(saved->deadTimeModes.value(4).normal, 60);
    QVERIFY(!saved->readAt.parts.contains(ProjectPart::DeadTimeModes));

    // Written from the modes page: both outputs, once each; no edit stays on either page.
    std::optional<WriteResult> result;
    modes->writeChanges([&](const WriteResult& r) { result = r; });
    QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), kDeviceTimeoutMs);
    QVERIFY2(result->ok() && (*result)->complete(), qPrintable(writeDetails(*result)));
    QCOMPARE((*result)->deadTimeModes.size(), 2);
    QCOMPARE(camConWorkspace(*shell)->changedCount(), before);
    QVERIFY(!model->isChanged(3));
    QVERIFY(!model->isChanged(4));
    QCOMPARE(modes->onDevice().value(3).normal, 45);
    QCOMPARE(camConWorkspace(*shell)->cams()->deviceDeadTime(4), std::optional<qint32>(60));

    // Read again from the device: both pages show what it holds.
    modes->readFromDevice();
    QTRY_COMPARE_WITH_TIMEOUT(modes->onDevice().value(4).normal, 60, kDeviceTimeoutMs);
    QCOMPARE(shownPlain(4), 6.0);
    QCOMPARE(camConWorkspace(*shell)->changedCount(), before);
}

void TablePageEditsTest::projectFileKeepsTheAnalogueCams() {
    // A saved project holds the analogue cams as the page shows them, an
    // edit included (they were left out of the file before).
    auto shell = startOnTable();
    QVERIFY(shell);
    auto* analogue = shell->window()->findChild<AnalogueCamsPage*>();
    QTRY_COMPARE_WITH_TIMEOUT(analogue->onDevice().points.size(), 3, kDeviceTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(!camConWindow(shell->window())->isReadingDevice(), kDeviceTimeoutMs);
    AnalogueCamTrack edited = analogue->onDevice();
    edited.points.last().value += 1;
    analogue->setEdited(edited);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.json"));
    QVERIFY(camConWindow(shell->window())->saveProjectTo(path).ok());
    const Result<Project> saved = loadProject(path);
    QVERIFY2(saved.ok(), qPrintable(saved.error().message));
    bool found = false;
    for (const AnalogueCamTrack& track : saved->analogueCams) found |= track == edited;
    QVERIFY(found);
}

void TablePageEditsTest::compareListsAndWritesTheTableSections() {
    auto shell = startOnTable();
    QVERIFY(shell);
    auto* lock = shell->window()->findChild<EepromLockPage*>();
    QTRY_VERIFY_WITH_TIMEOUT(lock->locked().has_value(), kDeviceTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(!camConWindow(shell->window())->isReadingDevice(), kDeviceTimeoutMs);
    Workspace* workspace = camConWorkspace(*shell);
    QTRY_VERIFY_WITH_TIMEOUT(workspace->programmingProgram().deviceValue().has_value(),
                             kDeviceTimeoutMs);

    // A project that wants other analogue points, programming program and lock.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.json"));
    QVERIFY(camConWindow(shell->window())->saveProjectTo(path).ok());
    Result<Project> saved = loadProject(path);
    QVERIFY2(saved.ok(), qPrintable(saved.error().message));
    QVERIFY(saved->programmingProgram.has_value());
    QCOMPARE(saved->eepromLock, std::optional<bool>(false));
    Project wanted = *saved;
    wanted.analogueCams = {AnalogueCamTrack{7, {{0, 10}, {90, 20}}}};
    wanted.programmingProgram = ProgrammingProgram{2, 1, 0};
    wanted.eepromLock = true;
    wanted.readAt = {};
    QVERIFY(saveProject(path, wanted).ok());
    const auto keep = answerReplaceEdits(false);
    camConWindow(shell->window())->openProjectFile(path);
    QVERIFY(workspace->analogueCams().changedKeys().contains(7));
    QVERIFY(workspace->programmingProgram().isChanged());
    QVERIFY(workspace->eepromLock().isChanged());

    CompareDialog* compare = camConWindow(shell->window())->openCompare();
    QTRY_VERIFY_WITH_TIMEOUT(!compare->isReading(), kDeviceTimeoutMs);
    QStringList listed;
    for (int i = 0; i < compare->tree()->topLevelItemCount(); ++i) {
        QTreeWidgetItem* section = compare->tree()->topLevelItem(i);
        for (int j = 0; j < section->childCount(); ++j)
            listed << section->child(j)->text(0) + QLatin1String(" | ") +
                          section->child(j)->text(1) + QLatin1String(" | ") +
                          section->child(j)->text(2);
    }
    const QString all = listed.join(QLatin1Char('\n'));
    QVERIFY2(all.contains(QLatin1String("Analogue output 7 | ")), qPrintable(all));
    QVERIFY2(all.contains(QLatin1String("Programming program | ")), qPrintable(all));
    QVERIFY2(all.contains(QLatin1String("EEPROM lock | unlocked | locked")), qPrintable(all));

    bool finished = false;
    connect(compare, &CompareDialog::writeFinished, this, [&finished] { finished = true; });
    compare->writeAll();
    QTRY_VERIFY_WITH_TIMEOUT(finished, kDeviceTimeoutMs);
    QVERIFY2(compare->reportText().contains(QLatin1String("EEPROM lock: written")),
             qPrintable(compare->reportText()));
    // The lock came last: nothing before it was kept in RAM only.
    QVERIFY2(!compare->reportText().contains(QLatin1String("RAM only")),
             qPrintable(compare->reportText()));
    QVERIFY(workspace->analogueCams().changedKeys().isEmpty());
    QVERIFY(!workspace->programmingProgram().isChanged());
    QVERIFY(!workspace->eepromLock().isChanged());
    QCOMPARE(lock->locked(), std::optional<bool>(true));
    QCOMPARE(workspace->analogueCams().deviceValue(7),
             std::optional<AnalogueCamTrack>(wanted.analogueCams.first()));

    // The report prints what the device holds now.
    QTextDocument report;
    CommissioningReport::build(report, *camConWorkspace(*shell));
    const QString text = report.toPlainText();
    QVERIFY2(text.contains(QLatin1String("Analogue cams")), qPrintable(text));
    QVERIFY2(text.contains(QLatin1String("Programming program")), qPrintable(text));
    QVERIFY2(text.contains(QLatin1String("EEPROM lock")), qPrintable(text));
    compare->close();
}

// Issue 12, point 3: settings read over the ASCII protocol that the table
// interface does not reach are not offered as edits after a read there.
void TablePageEditsTest::settingsOfAnotherProtocolAreNoEdits() {
    Workspace workspace;
    const SystemSettings ascii{{QStringLiteral("encoderText1"), QStringLiteral("Main axis")},
                               {QStringLiteral("speedFactor"), 100000},
                               {QStringLiteral("actualValueFormat"), 1}};
    workspace.settings().mergeWhole(ascii, true);
    workspace.settings().edit(QStringLiteral("actualValueFormat"), 2);  // edited by hand
    QCOMPARE(workspace.settings().changedKeys(), QStringList{QStringLiteral("actualValueFormat")});
    // The table interface has neither encoder texts nor the value format.
    workspace.settings().mergeWhole({{QStringLiteral("speedFactor"), 100000}}, true);
    QCOMPARE(workspace.settings().changedKeys(), QStringList{QStringLiteral("actualValueFormat")});
    QVERIFY(!workspace.settings().value(QStringLiteral("encoderText1")));
}

QTEST_MAIN(TablePageEditsTest)
#include "tst_table_page_edits.moc"
