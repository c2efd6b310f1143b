// Issue 27, items 1 and 7 (the shell's part): a STOP above every page while
// the device on the line can move something, its key from every widget and
// during a long job, ahead of what waits for the line; none for a CamCon;
// quitting or disconnecting while something moves asks first. Against the
// test-only fake family (its axes on the simulator: fake_family.h) with two
// devices that differ, and against the MC-1 and Compax3 simulators once
// their families give the shell a MotionControl.
#include "fake_family.h"

#include "../ui/shell/shell_fixture.h"

#include "ui/device_session.h"
#include "ui/main_window.h"
#include "ui/motion_stop.h"
#include "ui/section_page.h"
#include "ui/shell.h"
#include "ui/stop_bar.h"

#include <QAbstractItemView>
#include <QListWidget>
#include <QPushButton>
#include <QSemaphore>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTableWidget>
#include <QTest>

#include <atomic>
#include <functional>
#include <optional>

using namespace cambench;
using namespace cambench::test;

namespace {

constexpr int kTimeoutMs = 60000;  // bounds a wait; never a pass/fail threshold

QListWidget* navOf(MainWindow* window) {
    return window->findChild<QListWidget*>();
}

// Waits until every job submitted so far has answered: a User job's answer
// comes after the answers of the Urgent ones (the STOP's availability)
// queued before it.
bool settle(DeviceSession* session) {
    bool done = false;
    QObject context;
    session->worker().run<bool>(
        &context, comm::JobPriority::User, QStringLiteral("settle"),
        [](comm::JobContext&) { return true; }, [&done](bool) { done = true; });
    return QTest::qWaitFor([&done] { return done; }, kTimeoutMs);
}

// Runs `work` on the fake device through the worker and waits for it.
template <class T>
Result<T> onFake(DeviceSession* session,
                 std::function<Result<T>(fake::FakeDevice&, comm::JobContext&)> work) {
    std::optional<Result<T>> result;
    QObject context;
    session->run<fake::FakeDevice, T>(&context, QStringLiteral("test"), std::move(work),
                                      [&result](Result<T> r) { result = std::move(r); });
    if (!QTest::qWaitFor([&result] { return result.has_value(); }, kTimeoutMs))
        return Error::communication(QStringLiteral("no answer"));
    return *result;
}

Result<QStringList> movingOnFake(DeviceSession* session) {
    return onFake<QStringList>(
        session, [](fake::FakeDevice& device, comm::JobContext&) { return device.activeMotion(); });
}

bool moveFake(DeviceSession* session, int axis) {
    return onFake<QString>(session, [axis](fake::FakeDevice& device,
                                           comm::JobContext&) { return device.move(axis); })
        .ok();
}

bool activate(MainWindow* window) {
    window->show();
    window->activateWindow();
    return QTest::qWaitForWindowActive(window);
}

// The widget of the shown page that has (or can take) the focus.
QWidget* focusTarget(MainWindow* window, QWidget* page) {
    for (QWidget* child : page->findChildren<QWidget*>())
        if (child->isVisible() && child->isEnabled() && child->focusPolicy() != Qt::NoFocus)
            return child;
    return navOf(window);
}

// The page the window shows (the others of its stack are hidden).
QWidget* shownPage(MainWindow* window) {
    for (SectionPage* page : window->findChildren<SectionPage*>())
        if (page->isVisible()) return page;
    return nullptr;
}

// A shell on the fake device of `port`, every start job answered, the
// window shown and active; nullptr when any of it failed.
std::unique_ptr<Shell> startFake(const QString& port) {
    std::unique_ptr<Shell> shell = startOnSimulator(port, QStringLiteral("fake-line"));
    if (!shell || !settle(shell->session()) || !activate(shell->window())) return nullptr;
    return shell;
}

struct Row {
    QString port;
    QString protocol;
    int axes = 0;      // fake: how many; 0: a family of the product
    int deafAxis = 0;  // fake: the axis that never acknowledges a STOP
};

}  // namespace

Q_DECLARE_METATYPE(Row)

class TestMotionStop : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() {
        useTestSettings();
        fake::registerFakeFamily();
        qRegisterMetaType<comm::MotionStopReport>();
    }

    void stopAndItsKeyFromEveryPage_data() {
        QTest::addColumn<Row>("row");
        QTest::newRow("fake, one axis") << Row{QStringLiteral("sim:axes=1"), "fake-line", 1, 0};
        QTest::newRow("fake, three axes, axis 2 deaf")
            << Row{QStringLiteral("sim:axes=3;deaf=2"), "fake-line", 3, 2};
        QTest::newRow("mc200v2") << Row{QStringLiteral("sim:variant=mc200v2"), "mc1", 0, 0};
        QTest::newRow("compax3") << Row{QStringLiteral("sim"), "compax3", 0, 0};
    }

    void stopAndItsKeyFromEveryPage() {
        QFETCH(Row, row);
        std::unique_ptr<Shell> shell = startOnSimulator(row.port, row.protocol);
        QVERIFY(shell);
        MainWindow* window = shell->window();
        DeviceSession* session = shell->session();
        MotionStop* stop = session->motionStop();
        QVERIFY(settle(session));
        if (row.axes == 0 && !stop->available())
            QSKIP(
                "this family gives the shell no MotionControl on this branch yet; "
                "it must pass once the family's implementation is merged");
        QVERIFY(stop->available());
        QVERIFY(stop->armed());
        QVERIFY(activate(window));
        StopBar* bar = window->stopBar();
        QVERIFY(bar->isVisible());
        QVERIFY(bar->button()->isEnabled());
        QVERIFY(bar->button()->text().contains(QLatin1String("Esc")));
        QSignalSpy reports(stop, &MotionStop::stopFinished);
        QListWidget* nav = navOf(window);
        int pagesVisited = 0;
        for (int section = 0; section < window->sectionCount(); ++section) {
            if (nav->item(section)->isHidden()) continue;
            ++pagesVisited;
            window->showSection(section);
            QWidget* page = shownPage(window);
            QVERIFY(page);
            for (const bool byKey : {false, true}) {
                const QString how = QStringLiteral("%1, %2").arg(
                    nav->item(section)->text(),
                    byKey ? QStringLiteral("Escape") : QStringLiteral("button"));
                if (row.axes > 0) {
                    for (int axis = 1; axis <= row.axes; ++axis) QVERIFY(moveFake(session, axis));
                    fake::clearRequestLog();
                }
                const qsizetype before = reports.size();
                if (byKey) {
                    QVERIFY(activate(window));
                    QWidget* target = focusTarget(window, page);
                    target->setFocus();
                    QTest::keyClick(target, Qt::Key_Escape);
                } else {
                    bar->button()->click();
                }
                QVERIFY2(QTest::qWaitFor([&] { return reports.size() == before + 1; }, kTimeoutMs),
                         qPrintable(how));
                const auto report = reports.last().first().value<comm::MotionStopReport>();
                QVERIFY2(!report.lines.isEmpty(), qPrintable(how));
                if (row.axes == 0) {
                    QVERIFY2(report.allAcknowledged(), qPrintable(how + bar->reportText()));
                    continue;
                }
                // One STOP per axis, back to back, each reported.
                QStringList stops;
                for (int axis = 1; axis <= row.axes; ++axis)
                    stops << QStringLiteral("STOP %1").arg(axis);
                QCOMPARE(fake::requestLog(), stops);
                QCOMPARE(report.lines.size(), row.axes);
                for (int axis = 1; axis <= row.axes; ++axis) {
                    const QString line = axis == row.deafAxis
                                             ? QStringLiteral(
                                                   "Axis %1: NOT acknowledged – use "
                                                   "the machine's emergency stop")
                                             : QStringLiteral("Axis %1: acknowledged");
                    QVERIFY2(bar->reportText().contains(line.arg(axis)),
                             qPrintable(how + QLatin1Char('\n') + bar->reportText()));
                }
                const Result<QStringList> moving = movingOnFake(session);
                QVERIFY(moving.ok());
                QCOMPARE(*moving,
                         row.deafAxis
                             ? QStringList{QStringLiteral("axis %1 moves").arg(row.deafAxis)}
                             : QStringList{});
            }
        }
        QVERIFY(pagesVisited >= 2);  // the connection page and the family's
    }

    // Escape is also a spin box's and a cell editor's; the STOP key works
    // there too, and the editor still drops its edit.
    void stopKeyFromSpinBoxAndCellEditor() {
        std::unique_ptr<Shell> shell = startFake(QStringLiteral("sim:axes=1"));
        QVERIFY(shell);
        MainWindow* window = shell->window();
        MotionStop* stop = shell->session()->motionStop();
        QVERIFY(stop->armed());
        auto* page = window->findChild<SectionPage*>(QStringLiteral("fakePage"));
        window->showPage(page);
        QSignalSpy reports(stop, &MotionStop::stopFinished);

        auto* number = page->findChild<QSpinBox*>(QStringLiteral("fakeNumber"));
        number->setFocus();
        QTest::keyClick(number, Qt::Key_Escape);
        QVERIFY(QTest::qWaitFor([&] { return reports.size() == 1; }, kTimeoutMs));

        auto* table = page->findChild<QTableWidget*>(QStringLiteral("fakeTable"));
        table->setItem(0, 0, new QTableWidgetItem(QStringLiteral("kept")));
        table->setCurrentCell(0, 0);
        table->editItem(table->item(0, 0));
        QWidget* editor = QApplication::focusWidget();
        QVERIFY(editor && table->isAncestorOf(editor));
        QTest::keyClicks(editor, QStringLiteral("typed"));
        QTest::keyClick(editor, Qt::Key_Escape);
        QVERIFY(QTest::qWaitFor([&] { return reports.size() == 2; }, kTimeoutMs));
        QCOMPARE(table->item(0, 0)->text(), QStringLiteral("kept"));  // the edit was dropped
    }

    // A long job (a backup) is paused for the STOP between two of its
    // requests: the STOP does not wait for its end, and it goes on after.
    void stopDuringALongJobLandsBetweenItsRequests() {
        std::unique_ptr<Shell> shell = startFake(QStringLiteral("sim:axes=2"));
        QVERIFY(shell);
        DeviceSession* session = shell->session();
        MotionStop* stop = session->motionStop();
        QVERIFY(moveFake(session, 2));
        fake::clearRequestLog();
        QSemaphore gate;
        std::atomic_int pinged{0};
        std::optional<Result<QString>> backup;
        session->run<fake::FakeDevice, QString>(
            this, QStringLiteral("long job"),
            [&gate, &pinged](fake::FakeDevice& device, comm::JobContext&) -> Result<QString> {
                for (int n = 1; n <= 5; ++n) {
                    const Result<QString> pong = device.ping(n);
                    if (!pong) return pong;
                    if (++pinged == 2) gate.acquire();
                }
                return QStringLiteral("done");
            },
            [&backup](Result<QString> done) { backup = std::move(done); });
        QVERIFY(QTest::qWaitFor([&] { return pinged.load() == 2; }, kTimeoutMs));
        QSignalSpy reports(stop, &MotionStop::stopFinished);
        QWidget* focus = shell->window()->connectionPage();
        focus->setFocus();
        QTest::keyClick(focus, Qt::Key_Escape);
        gate.release();
        QVERIFY(
            QTest::qWaitFor([&] { return reports.size() == 1 && backup.has_value(); }, kTimeoutMs));
        QVERIFY2(backup->ok(), qPrintable(backup->error().message));  // not broken
        QCOMPARE(fake::requestLog(), QStringList({"PING 1", "PING 2", "STOP 1", "STOP 2", "PING 3",
                                                  "PING 4", "PING 5"}));
        QVERIFY(reports.first().first().value<comm::MotionStopReport>().allAcknowledged());
    }

    // A CamCon moves nothing: no STOP on screen, Escape is the widgets'.
    void noStopForACamCon() {
        std::unique_ptr<Shell> shell = startOnSimulator();
        QVERIFY(shell);
        QVERIFY(settle(shell->session()));
        MotionStop* stop = shell->session()->motionStop();
        QVERIFY(!stop->available());
        QVERIFY(activate(shell->window()));
        QVERIFY(!shell->window()->stopBar()->isVisible());
        QSignalSpy started(stop, &MotionStop::stopStarted);
        QListWidget* nav = navOf(shell->window());
        for (int section = 0; section < shell->window()->sectionCount(); ++section) {
            if (nav->item(section)->isHidden()) continue;
            shell->window()->showSection(section);
            QVERIFY(!shell->window()->stopBar()->isVisible());
            nav->setFocus();
            QTest::keyClick(nav, Qt::Key_Escape);
        }
        QCOMPARE(started.size(), 0);
    }

    // Quitting or disconnecting while an axis moves asks, naming it; cancel
    // keeps everything, "STOP, then …" stops first; nothing moving, nothing
    // is asked.
    void quitOrDisconnectWhileMovingAsks() {
        std::unique_ptr<Shell> shell = startFake(QStringLiteral("sim:axes=2"));
        QVERIFY(shell);
        MainWindow* window = shell->window();
        DeviceSession* session = shell->session();
        QVERIFY(moveFake(session, 2));

        QString asked;
        const auto answer = [&asked](const char* button) {
            return std::make_unique<NextDialog<QMessageBox>>([&asked, button](QMessageBox* box) {
                asked = box->text() + QLatin1Char('\n') + box->informativeText();
                if (QAbstractButton* b = box->findChild<QAbstractButton*>(QLatin1String(button)))
                    b->click();
                else
                    box->reject();
            });
        };
        {
            auto cancel = answer("nothing: cancel");
            QVERIFY(!window->close());
            QCOMPARE(cancel->answered(), 1);
        }
        QVERIFY2(asked.contains(QLatin1String("axis 2 moves")), qPrintable(asked));
        QCOMPARE(*movingOnFake(session), QStringList{QStringLiteral("axis 2 moves")});

        {
            auto leave = answer("leaveWithoutStop");
            session->disconnectFromDevice();
            QCOMPARE(leave->answered(), 1);
        }
        QVERIFY(QTest::qWaitFor([&] { return !session->isOnline(); }, kTimeoutMs));

        // Back on the line, the axis moving again: STOP, then quit.
        window->connectAndLoad();
        QVERIFY(QTest::qWaitFor([&] { return session->motionStop()->armed(); }, kTimeoutMs));
        QVERIFY(moveFake(session, 1));
        fake::clearRequestLog();
        {
            auto stopFirst = answer("stopThenLeave");
            QVERIFY(window->close());
            QCOMPARE(stopFirst->answered(), 1);
        }
        QVERIFY(fake::requestLog().contains(QStringLiteral("STOP 1")));
        QVERIFY(fake::requestLog().contains(QStringLiteral("STOP 2")));

        // Nothing moves: disconnecting asks nothing.
        QVERIFY(activate(window));
        QCOMPARE(*movingOnFake(session), QStringList{});
        auto none = answer("nothing");
        session->disconnectFromDevice();
        QVERIFY(QTest::qWaitFor([&] { return !session->isOnline(); }, kTimeoutMs));
        QCOMPARE(none->answered(), 0);
    }

    // A device that does not answer what moves: "could not tell" is said.
    void couldNotTellIsSaid() {
        std::unique_ptr<Shell> shell = startFake(QStringLiteral("sim:axes=1"));
        QVERIFY(shell);
        QVERIFY(shell->session()->motionStop()->armed());
        // Cancelled while the question waits for the answer: the worker is
        // busy with a job that holds the line, so no answer comes in time.
        QSemaphore gate;
        QSemaphore holding;
        shell->session()->worker().submit(comm::JobPriority::User, QStringLiteral("hold"),
                                          [&gate, &holding](comm::JobContext&) {
                                              holding.release();
                                              gate.acquire();
                                          });
        // Queued, an Urgent question would go ahead of it: wait until it runs.
        QVERIFY(holding.tryAcquire(1, kTimeoutMs));
        QString asked;
        NextDialog<QMessageBox> cancel([&asked](QMessageBox* box) {
            asked = box->text();
            box->reject();
        });
        QVERIFY(!shell->session()->mayLeaveDevice(QStringLiteral("Disconnect")));
        gate.release();
        QVERIFY2(asked.contains(QLatin1String("could not tell")), qPrintable(asked));
    }
};

QTEST_MAIN(TestMotionStop)
#include "tst_motion_stop.moc"
