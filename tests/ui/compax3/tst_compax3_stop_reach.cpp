// Issue 35 items 4 and 5 on a Compax3 (the in-process simulator): with the
// axis jogging, Escape inside every kind of dialog and menu stops it with
// exactly the STOP's telegrams and nothing else, the dialog cancelled; on
// RS485, choosing another address in the bus list while the drive moves
// asks first and offers STOP - the STOP never silently goes elsewhere.
#include "../shell/stop_reach_checks.h"

#include "ui/compax3/compax3_motion_page.h"
#include "ui/compax3/compax3_window.h"

#include <QListWidget>
#include <QMessageBox>

using namespace cambench;
using namespace cambench::test;

namespace {

struct Compax3Shell {
    std::unique_ptr<Shell> shell;
    Compax3MotionPage* motion = nullptr;
};

Compax3Shell startDrive(const QString& port, const QString& protocol) {
    Compax3Shell started;
    started.shell = startOnSimulator(port, protocol);
    if (!started.shell) return started;
    started.motion = compax3Window(started.shell->window())->motionPage();
    MotionStop* stop = started.shell->session()->motionStop();
    if (!QTest::qWaitFor([stop] { return stop->armed(); }, kDeviceTimeoutMs)) started.shell.reset();
    return started;
}

bool says(Compax3MotionPage* motion, const char* start) {
    return motion->axisText().startsWith(QLatin1String(start));
}

// Powers the drive (once) and jogs it (confirmed as a person does), then
// shows the Connection page: no page polls, the line is quiet but for what
// the test does.
bool jog(const Compax3Shell& c3) {
    MainWindow* window = c3.shell->window();
    Compax3MotionPage* motion = c3.motion;
    window->showPage(motion);
    if (!QTest::qWaitFor([motion] { return motion->freshness()->isLive(); }, kDeviceTimeoutMs))
        return false;
    if (!says(motion, "Powered")) {
        const auto yes = answerConfirmation(true);
        motion->runMotion(comm::Compax3Motion::Enable);
        if (!QTest::qWaitFor([motion] { return says(motion, "Powered"); }, kDeviceTimeoutMs))
            return false;
    }
    {
        const auto yes = answerConfirmation(true);
        motion->runMotion(comm::Compax3Motion::JogPlus);
    }
    if (!QTest::qWaitFor([motion] { return says(motion, "Moving"); }, kDeviceTimeoutMs))
        return false;
    return leaveForQuietPage(window, motion);
}

}  // namespace

class TestCompax3StopReach : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() {
        useTestSettings();
        qRegisterMetaType<comm::MotionStopReport>();
    }

    void escapeInEveryDialogAndMenuStopsTheJog() {
        const Compax3Shell c3 = startDrive(QStringLiteral("sim"), QStringLiteral("compax3"));
        QVERIFY(c3.shell);
        // A jog's confirmation: cancelled, the jog − is not sent.
        Compax3MotionPage* motion = c3.motion;
        escapeStopsEverywhereIn(c3.shell->window(),
                                {QStringLiteral("jog confirmation"),
                                 [motion] { motion->runMotion(comm::Compax3Motion::JogMinus); }},
                                [&c3] { return jog(c3); });
    }

    // Item 5: a double click on another address while the drive jogs asks
    // (naming what moves), Cancel keeps the drive and the STOP where they
    // are; "STOP, then switch" stops it first and then switches.
    void anotherAddressWhileMovingAsksFirst() {
        const Compax3Shell c3 =
            startDrive(QStringLiteral("sim:address=0"), QStringLiteral("compax3-rs485"));
        QVERIFY(c3.shell);
        DeviceSession* session = c3.shell->session();
        MotionStop* stop = session->motionStop();
        QCOMPARE(session->protocol().device(), 0);
        auto* list = c3.shell->window()->connectionPage()->findChild<QListWidget*>(
            QStringLiteral("busDevices"));
        QVERIFY(list);
        // As a bus scan lists them: the drive on the line and one at 5.
        for (int address : {0, 5}) {
            auto* item = new QListWidgetItem(QStringLiteral("Compax3 at %1").arg(address), list);
            item->setData(Qt::UserRole, address);
        }
        QListWidgetItem* other = list->item(1);

        QVERIFY(jog(c3));
        QString asked;
        {
            NextDialog<QMessageBox> cancel([&asked](QMessageBox* box) {
                asked = box->text() + QLatin1Char('\n') + box->informativeText();
                box->reject();
            });
            Q_EMIT list->itemActivated(other);
            QCOMPARE(cancel.answered(), 1);
        }
        QVERIFY2(asked.contains(QLatin1String("moves")), qPrintable(asked));
        QCOMPARE(session->protocol().device(), 0);  // the STOP still reaches the jogging drive
        QVERIFY(!nothingMoves(stop));

        QSignalSpy reports(stop, &StopControl::stopFinished);
        {
            NextDialog<QMessageBox> stopFirst([](QMessageBox* box) {
                box->findChild<QAbstractButton*>(QStringLiteral("stopThenLeave"))->click();
            });
            Q_EMIT list->itemActivated(other);
            QCOMPARE(stopFirst.answered(), 1);
        }
        QCOMPARE(reports.size(), 1);
        QVERIFY(reports.first().first().value<comm::MotionStopReport>().allAcknowledged());
        QCOMPARE(session->protocol().device(), 5);

        // Nothing answers at 5: switching back cannot tell what moves
        // there, and says so before it goes.
        QVERIFY(QTest::qWaitFor([&] { return stop->armed(); }, kDeviceTimeoutMs));
        {
            NextDialog<QMessageBox> couldNotTell([&asked](QMessageBox* box) {
                asked = box->text();
                box->findChild<QAbstractButton*>(QStringLiteral("leaveWithoutStop"))->click();
            });
            Q_EMIT list->itemActivated(list->item(0));
            QCOMPARE(couldNotTell.answered(), 1);
        }
        QVERIFY2(asked.contains(QLatin1String("could not tell")), qPrintable(asked));
        QCOMPARE(session->protocol().device(), 0);
    }
};

QTEST_MAIN(TestCompax3StopReach)
#include "tst_compax3_stop_reach.moc"
