// Issue 35 items 4 and 10 on an MC200 V2 (the in-process simulator): with
// an axis jogging, Escape inside every kind of dialog and menu - and the
// STOP every dialog shows - stops it with exactly the STOP's telegrams and
// nothing else, the dialog cancelled; a STOP's report moves no button of
// the Axes page.
#include "../shell/stop_reach_checks.h"
#include "mc1_jog.h"

#include "ui/mc1/mc1_axes_page.h"
#include "ui/mc1/mc1_window.h"

#include <QLabel>
#include <QMessageBox>
#include <QSpinBox>

using namespace cambench;
using namespace cambench::test;

namespace {

struct Mc1Shell {
    std::unique_ptr<Shell> shell;
    Mc1AxesPage* axes = nullptr;
};

Mc1Shell startMc200() {
    Mc1Shell started;
    started.shell = startOnSimulator(QStringLiteral("sim:variant=mc200v2"), QStringLiteral("mc1"));
    if (!started.shell) return started;
    started.axes = mc1Window(started.shell->window())->axesPage();
    MotionStop* stop = started.shell->session()->motionStop();
    if (!QTest::qWaitFor([stop] { return stop->armed(); }, kDeviceTimeoutMs)) started.shell.reset();
    return started;
}

// Jogs axis 1, then shows the Connection page: the line is quiet but for
// what the test does.
bool jog(const Mc1Shell& mc1) {
    return jogPlus(mc1.shell->window(), mc1.axes) &&
           leaveForQuietPage(mc1.shell->window(), mc1.axes);
}

// Where each widget a person clicks on the page sits in the window.
QList<QRect> clickablePlaces(QWidget* page, QWidget* window) {
    QList<QRect> places;
    for (QWidget* widget : page->findChildren<QWidget*>()) {
        if (!qobject_cast<QPushButton*>(widget) && !qobject_cast<QSpinBox*>(widget)) continue;
        places << QRect(widget->mapTo(window, QPoint(0, 0)), widget->size());
    }
    return places;
}

}  // namespace

class TestMc1StopReach : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() {
        useTestSettings();
        qRegisterMetaType<comm::MotionStopReport>();
    }

    void escapeInEveryDialogAndMenuStopsTheJog() {
        const Mc1Shell mc1 = startMc200();
        QVERIFY(mc1.shell);
        // A move's confirmation: cancelled, the jog − is not sent.
        Mc1AxesPage* axes = mc1.axes;
        escapeStopsEverywhereIn(mc1.shell->window(),
                                {QStringLiteral("move confirmation"),
                                 [axes] { axes->command(comm::Mc1AxisCommand::JogMinus); }},
                                [&mc1] { return jog(mc1); });
    }

    // The STOP a dialog shows works while the dialog stays open (a modal
    // dialog blocks the window's STOP bar).
    void theStopInADialogStopsAndLeavesItOpen() {
        const Mc1Shell mc1 = startMc200();
        QVERIFY(mc1.shell);
        DeviceSession* session = mc1.shell->session();
        MotionStop* stop = session->motionStop();
        QVERIFY(jog(mc1));
        QSignalSpy reports(stop, &StopControl::stopFinished);
        bool openAfter = false;
        QString why;
        NextDialog<QMessageBox> inside([&](QMessageBox* box) {
            DialogStop* row = DialogStop::of(box);
            if (!row) {
                why = QStringLiteral("no STOP in the confirmation");
                box->reject();
                return;
            }
            row->button()->click();
            (void)QTest::qWaitFor([&] { return reports.size() == 1; }, kDeviceTimeoutMs);
            openAfter = box->isVisible();
            why = row->reportText();
            box->reject();
        });
        mc1.axes->command(comm::Mc1AxisCommand::JogMinus);
        QCOMPARE(inside.answered(), 1);
        QCOMPARE(reports.size(), 1);
        QVERIFY(openAfter);
        QVERIFY2(why.contains(QLatin1String("STOP acknowledged")), qPrintable(why));
        QString said;
        QVERIFY2(nothingMoves(stop, &said), qPrintable(said));
    }

    // Item 10: the STOP's report (a line per axis) moves nothing a person
    // clicks on the page; the bar keeps its height.
    void aStopReportMovesNoButton() {
        const Mc1Shell mc1 = startMc200();
        QVERIFY(mc1.shell);
        MainWindow* window = mc1.shell->window();
        MotionStop* stop = mc1.shell->session()->motionStop();
        window->showPage(mc1.axes);
        QVERIFY(QTest::qWaitFor([&] { return mc1.axes->freshness()->isLive(); }, kDeviceTimeoutMs));
        QTest::qWait(50);  // laid out
        const QList<QRect> before = clickablePlaces(mc1.axes, window);
        const int barHeight = window->stopBar()->height();
        QVERIFY(!before.isEmpty());
        QSignalSpy reports(stop, &StopControl::stopFinished);
        window->stopBar()->button()->click();
        QVERIFY(reports.wait(kDeviceTimeoutMs));
        QVERIFY(QTest::qWaitFor([&] { return mc1.axes->freshness()->isLive(); }, kDeviceTimeoutMs));
        QTest::qWait(50);
        const QString report = window->stopBar()->reportText();
        QVERIFY2(report.count(QLatin1Char('\n')) >= 2, qPrintable(report));  // several lines
        QCOMPARE(window->stopBar()->height(), barHeight);
        QCOMPARE(clickablePlaces(mc1.axes, window), before);
    }
};

QTEST_MAIN(TestMc1StopReach)
#include "tst_mc1_stop_reach.moc"
