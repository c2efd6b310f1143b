// Issue 14: the MC-1 pages on real widgets against the simulated MC200 V2
// (and an MC100 V1) through the real worker: what they show is what the
// controller holds, every write and motion asks first, STOP and Escape
// stop a moving axis, and a lost line makes the values stale.
#include "../shell/shell_fixture.h"

#include "ui/device_session.h"
#include "ui/led_strip.h"
#include "ui/mc1/mc1_axes_page.h"
#include "ui/mc1/mc1_points_page.h"
#include "ui/mc1/mc1_program_page.h"
#include "ui/mc1/mc1_variables_page.h"
#include "ui/mc1/mc1_watch_model.h"
#include "ui/mc1/mc1_window.h"

#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTemporaryDir>

using namespace cambench;
using namespace cambench::test;

namespace {

std::unique_ptr<Shell> startMc1(const QString& variant) {
    return startOnSimulator(QStringLiteral("sim:variant=%1").arg(variant), QStringLiteral("mc1"));
}

}  // namespace

class Mc1PagesTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { useTestSettings(); }

    void variablesAreLiveAndWrittenOnlyAfterYes() {
        std::unique_ptr<Shell> shell = startMc1(QStringLiteral("mc200v2"));
        QVERIFY(shell);
        Mc1Window* mc1 = mc1Window(shell->window());
        QVERIFY(mc1);
        QVERIFY(mc1->facts().known);
        QCOMPARE(mc1->facts().variant, comm::Mc1Variant::Mc200V2);
        shell->window()->showPage(mc1->variablesPage());
        Mc1WatchModel* model = mc1->variablesPage()->model();
        // The simulator's demo values V1 = -250, V2 = -150, ...
        QVERIFY(QTest::qWaitFor([&] { return model->entries().value(1).value.has_value(); },
                                kDeviceTimeoutMs));
        QCOMPARE(*model->entries().at(1).value, qint64(-150));
        QCOMPARE(model->index(1, Mc1WatchModel::StateColumn).data().toString(),
                 QStringLiteral("live"));

        // An edit is a request: No leaves the controller as it is.
        {
            auto no = answerConfirmation(false);
            model->setData(model->index(1, Mc1WatchModel::ValueColumn), 77, Qt::EditRole);
            QCOMPARE(no->answered(), 1);
        }
        QTest::qWait(600);
        QCOMPARE(*model->entries().at(1).value, qint64(-150));
        auto yes = answerConfirmation(true);
        model->setData(model->index(1, Mc1WatchModel::ValueColumn), 77, Qt::EditRole);
        QVERIFY(
            QTest::qWaitFor([&] { return *model->entries().at(1).value == 77; }, kDeviceTimeoutMs));
        const QLabel* result =
            mc1->variablesPage()->findChild<QLabel*>(QStringLiteral("pageResult"));
        QVERIFY2(result->text().contains(QLatin1String("V2 = 77 written and read back")),
                 qPrintable(result->text()));

        // The watch list, named, to a project file and back: values from
        // the file are not shown as live.
        model->setData(model->index(1, Mc1WatchModel::NameColumn), QStringLiteral("Feed length"),
                       Qt::EditRole);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("watch.json"));
        mc1->variablesPage()->saveList(path);
        model->removeRows({0, 1, 2});
        {
            // "Not moving" read through the guessed parameter numbers is no
            // fact: the disconnect asks (issue 35).
            auto leave = answerLeaveQuestion(QStringLiteral("leaveWithoutStop"));
            shell->session()->disconnectFromDevice();
            QCOMPARE(leave->answered(), 1);
        }
        mc1->variablesPage()->openList(path);
        QCOMPARE(model->entries().size(), 10);
        QCOMPARE(model->entries().at(1).name, QStringLiteral("Feed length"));
        QCOMPARE(*model->entries().at(1).value, qint64(77));
        QCOMPARE(model->index(1, Mc1WatchModel::StateColumn).data().toString(),
                 QStringLiteral("from the file, not read"));
        shell->session()->reconnect();
        QVERIFY(QTest::qWaitFor(
            [&] {
                return model->index(1, Mc1WatchModel::StateColumn).data().toString() ==
                       QLatin1String("live");
            },
            kDeviceTimeoutMs));

        // The line goes: values stay, marked stale since the last answer.
        {
            // "Not moving" read through the guessed parameter numbers is no
            // fact: the disconnect asks (issue 35).
            auto leave = answerLeaveQuestion(QStringLiteral("leaveWithoutStop"));
            shell->session()->disconnectFromDevice();
            QCOMPARE(leave->answered(), 1);
        }
        QVERIFY(QTest::qWaitFor([&] { return model->entries().at(1).stale; }, kDeviceTimeoutMs));
        QVERIFY(model->index(1, Mc1WatchModel::StateColumn)
                    .data()
                    .toString()
                    .startsWith(QLatin1String("no answer since ")));
    }

    void anOutputIsSetOnlyAfterYes() {
        std::unique_ptr<Shell> shell = startMc1(QStringLiteral("mc200v2"));
        QVERIFY(shell);
        Mc1Window* mc1 = mc1Window(shell->window());
        Mc1PointsPage* page = mc1->pointsPage();
        shell->window()->showPage(page);
        LedStrip* outputs = page->strip(comm::Mc1Area::Output);
        QVERIFY(QTest::qWaitFor([&] { return !outputs->isStale(); }, kDeviceTimeoutMs));
        QCOMPARE(outputs->states().value(2), true);   // the demo's A3
        QCOMPARE(outputs->states().value(5), false);  // A6
        auto yes = answerConfirmation(true);
        Q_EMIT outputs->ledClicked(5);
        QVERIFY(QTest::qWaitFor([&] { return outputs->states().value(5); }, kDeviceTimeoutMs));
        QCOMPARE(yes->answered(), 1);
    }

    void stopAndEscapeStopAMovingAxis() {
        std::unique_ptr<Shell> shell = startMc1(QStringLiteral("mc200v2"));
        QVERIFY(shell);
        Mc1AxesPage* axes = mc1Window(shell->window())->axesPage();
        shell->window()->showPage(axes);
        shell->window()->show();
        shell->window()->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(shell->window()));
        QVERIFY(axes->stopButton()->isVisible());
        QVERIFY(axes->stopButton()->isEnabled());
        for (bool escape : {false, true}) {
            {
                auto yes = answerConfirmation(true);
                axes->command(comm::Mc1AxisCommand::MoveRelative, 100000);
                QVERIFY(QTest::qWaitFor(
                    [&] { return axes->stateLabel()->text().contains(QLatin1String("moving")); },
                    kDeviceTimeoutMs));
            }
            if (escape) {
                // The window is active again after the confirmation (offscreen
                // does not do that by itself); the focus is wherever it was.
                shell->window()->activateWindow();
                QVERIFY(QTest::qWaitForWindowActive(shell->window()));
                QTest::keyClick(axes->stopButton(), Qt::Key_Escape);
            } else
                axes->stopButton()->click();
            const bool stopped = QTest::qWaitFor(
                [&] { return axes->stateLabel()->text().contains(QLatin1String("stands at")); },
                kDeviceTimeoutMs);
            QVERIFY2(
                stopped,
                qPrintable(QStringLiteral("%1 / %2 (escape %3)")
                               .arg(axes->stateLabel()->text(),
                                    axes->findChild<QLabel*>(QStringLiteral("pageResult"))->text())
                               .arg(escape)));
        }
        // A move the user does not confirm is never sent.
        auto no = answerConfirmation(false);
        axes->command(comm::Mc1AxisCommand::Home);
        QTest::qWait(700);
        QVERIFY(axes->stateLabel()->text().contains(QLatin1String("stands at")));
    }

    void anMc100SaysWhatItLacks() {
        std::unique_ptr<Shell> shell = startMc1(QStringLiteral("mc100v1"));
        QVERIFY(shell);
        Mc1Window* mc1 = mc1Window(shell->window());
        QCOMPARE(mc1->facts().variant, comm::Mc1Variant::Mc100V1);
        // Offered until the controller is identified (a STOP never waits
        // for a probe), then withdrawn.
        QVERIFY(QTest::qWaitFor([&] { return !mc1->axesPage()->stopButton()->isEnabled(); },
                                kDeviceTimeoutMs));
        auto* start = mc1->programPage()->findChild<QPushButton*>(QStringLiteral("mc1Start"));
        QVERIFY(!start->isEnabled());
        bool said = false;
        for (QLabel* label : mc1->programPage()->findChildren<QLabel*>())
            said =
                said || label->text().contains(QLatin1String("MC100 V1 has no program telegrams"));
        QVERIFY(said);
    }
};

QTEST_MAIN(Mc1PagesTest)
#include "tst_mc1_pages.moc"
