// The CamCon's Compare with device and Compare programs against the
// in-process simulator: the differences listed and drawn, only the checked
// ones written, what was not checked kept as an edit.
#include "camcon_fixture.h"

#include "ui/camcon/compare_dialog.h"
#include "ui/camcon/compare_programs_dialog.h"
#include "ui/camcon/program_diff_view.h"
#include "ui/language.h"

#include <QAbstractButton>
#include <QCheckBox>
#include <QListWidget>
#include <QMessageBox>
#include <QtTest>

using namespace cambench;
using namespace cambench::test;

class CompareDialogsTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    // As the application does at start: English catalogue (plural forms).
    void initTestCase() {
        useTestSettings();
        QVERIFY(setLanguage(QStringLiteral("en")));
    }
    void compareWritesOnlySelectedItems();
    void compareProgramsDrawsAndListsTheDifferences();
    void compareProgramsWritesOnlyTheCheckedDifferences();
};

void CompareDialogsTest::compareWritesOnlySelectedItems() {
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

void CompareDialogsTest::compareProgramsDrawsAndListsTheDifferences() {
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

void CompareDialogsTest::compareProgramsWritesOnlyTheCheckedDifferences() {
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

QTEST_MAIN(CompareDialogsTest)
#include "tst_compare_dialogs.moc"
