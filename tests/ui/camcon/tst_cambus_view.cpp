// Issue 16: Cam-BUS in the GUI on real widgets, through the real worker, on
// the in-process simulated bus (CamCons 0 and 7, a display 12): the
// connection page offers the PC's number, the bus view shows every user
// with the master and this PC marked, stays live while no job runs (the
// worker answers the bus between jobs), and says it is not live once the
// line is gone.
#include "../shell/shell_fixture.h"

#include "ui/camcon/cambus/cambus_settings_widget.h"
#include "ui/camcon/cambus/cambus_view_widget.h"
#include "ui/connection_page.h"
#include "ui/connection_status.h"
#include "ui/device_session.h"

#include <QLabel>
#include <QPushButton>
#include <QSpinBox>

using namespace cambench;
using namespace cambench::test;

class CamBusViewTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { useTestSettings(); }

    void theBusViewShowsEveryUserLive() {
        std::unique_ptr<Shell> shell = startOnSimulator(
            QStringLiteral("sim:devices=0,7;display=12"), QStringLiteral("cambus"));
        QVERIFY(shell);
        ConnectionPage* page = shell->window()->connectionPage();
        auto* settings = page->findChild<CamBusSettingsWidget*>();
        QVERIFY(settings);
        QCOMPARE(settings->numberField(QStringLiteral("pc-number"))->value(), 63);
        CamBusView* view = settings->busView();
        QVERIFY(QTest::qWaitFor(
            [view] {
                return view->shownUsers() == QList<int>({0, 7, 12, 63});
            },
            kDeviceTimeoutMs));
        // No job for a while: the worker keeps answering the bus, the view
        // stays live and the PC stays in the table.
        QTest::qWait(2500);
        view->refresh();
        QVERIFY2(!view->summaryText().contains(QLatin1String("Not live")),
                 qPrintable(view->summaryText()));
        QVERIFY2(view->summaryText().contains(QStringLiteral("4 users · master 0")),
                 qPrintable(view->summaryText()));
        QCOMPARE(view->shownUsers(), QList<int>({0, 7, 12, 63}));
        QVERIFY(view->shownUsers().contains(view->highlightedUser()));
        auto* pc = view->findChild<QLabel*>(QStringLiteral("camBusUser63"));
        QVERIFY(pc);
        QCOMPARE(pc->text(), QStringLiteral("63 PC"));
        QCOMPARE(view->findChild<QLabel*>(QStringLiteral("camBusUser0"))->text(),
                 QStringLiteral("0 M"));

        // Disconnected: what was heard is shown as that, not as live.
        QPushButton* disconnect = nullptr;
        for (QPushButton* button : page->findChildren<QPushButton*>())
            if (button->text() == QLatin1String("Disconnect")) disconnect = button;
        QVERIFY(disconnect);
        disconnect->click();
        QVERIFY(QTest::qWaitFor(
            [view] {
                view->refresh();
                return view->summaryText().startsWith(QLatin1String("Not live")) ||
                       view->summaryText().startsWith(QLatin1String("Not on a Cam-BUS"));
            },
            kDeviceTimeoutMs));
        QCOMPARE(view->highlightedUser(), -1);
    }

    // Issue 36 item 7: a Cam-BUS connection starts on a device that
    // answers; the form's device 0 is not on this bus (CamCons 3 and 5).
    void aConnectionStartsOnADeviceThatAnswers() {
        Shell shell;
        shell.start(QStringLiteral("sim:devices=3,5"), QStringLiteral("cambus"));
        DeviceSession* session = shell.window()->session();
        QCOMPARE(session->protocol().device(), 0);
        QVERIFY(QTest::qWaitFor(
            [session] { return session->deviceChecked() && session->protocol().device() == 3; },
            kDeviceTimeoutMs));
        QVERIFY2(
            shell.window()->connectionStrip()->text().contains(QLatin1String("device number 3")),
            qPrintable(shell.window()->connectionStrip()->text()));
        QVERIFY(session->identifyProblem().isEmpty());
    }
};

QTEST_MAIN(CamBusViewTest)
#include "tst_cambus_view.moc"
