// The connection page's family choice and Detect (issue 13, point 3): the
// real GUI, the real QSerialPort, a simulated CamCon on a pseudo-terminal
// that speaks the table interface (or nothing at all). Where Detect's
// behaviour needs only some family, the test-only fake family
// (tests/family/fake_family.h; registered after the built-in ones, so
// tried last).
#include "fake_shell_fixture.h"

#include "ui/device_session.h"
#include "ui/motion_stop.h"

#include "comm/sim/camcon/sim_demo.h"
#include "comm/sim/sim_pacer.h"
#include "comm/sim/sim_pty_server.h"
#include "comm/sim/simulator_registry.h"

#include <QComboBox>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QStandardItemModel>

#include <optional>

using namespace cambench;
using namespace cambench::test;

namespace {

// A simulated CamCon on a pty speaking `protocol`; `dead`: never answers.
class PtyDevice {
public:
    PtyDevice(const QString& protocol, bool dead = false) {
        comm::SimPortConfig config;
        config.throttle = false;
        config.faults.dead = dead;
        comm::applySimProtocol(config, protocol);
        m_line = comm::makeSimEndpoint(config);
        m_server = std::make_unique<comm::SimPtyServer>(*m_line, m_pacer);
        m_open = m_server->open().ok();
    }
    bool isOpen() const { return m_open; }
    QString path() const { return m_server->slavePath(); }

private:
    std::unique_ptr<comm::SimEndpoint> m_line;
    comm::SimPacer m_pacer{9600, false};
    std::unique_ptr<comm::SimPtyServer> m_server;
    bool m_open = false;
};

// A fake device (two axes) on a pty, as its family's simulator makes it.
class PtyFake {
public:
    PtyFake() {
        const comm::SimulatorInfo* simulator =
            comm::SimulatorRegistry::instance().forProtocol(QStringLiteral("fake-line"));
        Result<comm::SimulatedLine> line =
            simulator->fromPort(QStringLiteral("sim:axes=2"), {}, QStringLiteral("fake-line"));
        if (!line) return;
        m_line = std::move(line).value();
        m_server = std::make_unique<comm::SimPtyServer>(*m_line->endpoint, m_line->pacer);
        m_open = m_server->open().ok();
    }
    bool isOpen() const { return m_open; }
    QString path() const { return m_server->slavePath(); }

private:
    std::optional<comm::SimulatedLine> m_line;
    std::unique_ptr<comm::SimPtyServer> m_server;
    bool m_open = false;
};

QString waitForDetect(ConnectionPage* page) {
    auto* result = page->findChild<QLabel*>(QStringLiteral("detectResult"));
    (void)QTest::qWaitFor(
        [result] {
            return result->isVisible() && !result->text().startsWith(QLatin1String("Detecting"));
        },
        kDeviceTimeoutMs);
    return result->text();
}

}  // namespace

class TestDetect : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { QVERIFY(setUpWithTheFakeFamily()); }

    // Every family is offered (one not built yet would be greyed:
    // tst_fake_family); the protocol list is the family's.
    void familiesAndTheirProtocols() {
        Shell shell;
        shell.start(QStringLiteral("sim:throttle=0"), QStringLiteral("3964r-n96"));
        ConnectionPage* page = shell.window()->connectionPage();
        auto* families = page->findChild<QComboBox*>(QStringLiteral("familyBox"));
        QVERIFY(families);
        QCOMPARE(page->family(), QStringLiteral("camcon"));
        const int compax3 = families->findData(QStringLiteral("compax3"));
        QVERIFY(compax3 >= 0);
        const auto* model = qobject_cast<QStandardItemModel*>(families->model());
        QVERIFY(model->item(compax3)->flags() & Qt::ItemIsEnabled);
        QVERIFY(model->item(families->findData(QStringLiteral("mc1")))->flags() &
                Qt::ItemIsEnabled);
        QCOMPARE(page->protocolSettings()->protocolId(), QStringLiteral("3964r-n96"));
    }

    // A table-interface CamCon on a pty: Detect closes the connection (after
    // asking), finds it, fills in protocol and baud rate; Connect then reads it.
    void detectFindsTheTableInterface() {
        PtyDevice device(QStringLiteral("3964r-n96"));
        QVERIFY(device.isOpen());
        std::unique_ptr<Shell> shell = startOnSimulator();
        QVERIFY(shell);
        ConnectionPage* page = shell->window()->connectionPage();
        page->setPort(device.path());
        NextDialog<QMessageBox> yes(
            [](QMessageBox* box) { box->button(QMessageBox::Yes)->click(); });
        page->findChild<QPushButton*>(QStringLiteral("detectButton"))->click();
        const QString text = waitForDetect(page);
        QVERIFY2(text.contains(QLatin1String("Found on")), qPrintable(text));
        QVERIFY2(text.contains(QLatin1String("3964r-n96")), qPrintable(text));
        QCOMPARE(yes.answered(), 1);
        QCOMPARE(shell->session()->state(), comm::ConnectionState::Disconnected);
        QCOMPARE(page->protocolSettings()->protocolId(), QStringLiteral("3964r-n96"));
        QCOMPARE(page->connectionSettings().serial.baud, 9600);
        QCOMPARE(page->connectionSettings().port, device.path());

        QSignalSpy loaded(shell->window(), &MainWindow::loaded);
        shell->window()->connectAndLoad();
        QVERIFY(loaded.wait(kDeviceTimeoutMs));
        QVERIFY(loaded.first().first().toBool());
        QCOMPARE(shell->session()->protocol().protocolId(), QStringLiteral("3964r-n96"));
    }

    // Issue 28 item 4: the red failure of an earlier connect is not the
    // state of a port where Detect found a device: it goes, and the
    // result is not red.
    void aConnectFailureGoesWhenDetectFinds() {
        PtyFake device;
        QVERIFY(device.isOpen());
        std::unique_ptr<Shell> shell = startOnFake();
        QVERIFY(shell);
        ConnectionPage* page = shell->window()->connectionPage();
        auto* failure = page->findChild<QLabel*>(QStringLiteral("connectFailure"));
        QVERIFY(failure);
        page->setPort(QStringLiteral("/dev/cambench-no-such-port"));
        shell->window()->connectAndLoad();
        QTRY_VERIFY_WITH_TIMEOUT(failure->isVisible(), kDeviceTimeoutMs);
        NextDialog<QMessageBox> yes(
            [](QMessageBox* box) { box->button(QMessageBox::Yes)->click(); });
        page->setPort(device.path());
        page->detect();
        const QString text = waitForDetect(page);
        QVERIFY2(text.contains(QLatin1String("Found on")), qPrintable(text));
        QVERIFY2(text.contains(QLatin1String("fake-line")), qPrintable(text));
        QVERIFY(!failure->isVisible());
        const auto* result = page->findChild<QLabel*>(QStringLiteral("detectResult"));
        QVERIFY(result->palette().color(QPalette::WindowText) != QColor(0xd0, 0x30, 0x20));
    }

    // Nothing answers: every protocol tried is named, and what to check.
    void nothingAnswersNamesEveryTry() {
        PtyDevice device(QStringLiteral("standard"), true);
        QVERIFY(device.isOpen());
        Shell shell;
        shell.start(device.path(), QStringLiteral("standard"));
        ConnectionPage* page = shell.window()->connectionPage();
        QVERIFY(QTest::qWaitFor(
            [&] { return shell.session()->state() != comm::ConnectionState::Connecting; },
            kDeviceTimeoutMs));
        // Whether or not the first connect counts as connected, a question
        // may come: answer it.
        NextDialog<QMessageBox> yes(
            [](QMessageBox* box) { box->button(QMessageBox::Yes)->click(); });
        page->detect();
        const QString text = waitForDetect(page);
        QVERIFY2(text.contains(QLatin1String("Nothing answered on ") + device.path()),
                 qPrintable(text));
        // One short line per try on the page, what each said in full in the tooltip.
        // The fake family, registered after the built-in ones, is tried last.
        QCOMPARE(text.count(QLatin1String(": no answer")), 10);
        for (const char* title :
             {"Cam-BUS", "Standard", "Multiuser", "3964R n96", "3964R e38", "MC-1", "MC100 ASCII",
              "Compax3 ASCII (RS232)", "Compax3 ASCII (RS485)", "Fake line protocol"})
            QVERIFY2(text.contains(QLatin1String(title)), qPrintable(text));
        // Cam-BUS only listens, and before the others' bytes could disturb a bus.
        QVERIFY2(text.indexOf(QLatin1String("Cam-BUS")) < text.indexOf(QLatin1String("Standard")),
                 qPrintable(text));
        QVERIFY2(text.indexOf(QLatin1String("Fake line protocol")) >
                     text.indexOf(QLatin1String("Compax3 ASCII (RS485)")),
                 qPrintable(text));
        const QString details = page->findChild<QLabel*>(QStringLiteral("detectResult"))->toolTip();
        for (const char* protocol : {"cambus", "standard", "multiuser", "3964r-n96", "3964r-e38",
                                     "mc1", "mc1-ascii", "compax3", "compax3-rs485", "fake-line"})
            QVERIFY2(details.contains(QLatin1String(protocol)), qPrintable(details));
        QVERIFY(text.contains(QLatin1String("Check the cable")));
    }

    // A device that can move is on the line (a fake one with axes): Detect
    // asks its own question, then the one before leaving a moving device.
    // Cancelled there, Detect stops: the line stays, nothing is sent, no
    // detection starts.
    void detectStopsWhenLeavingTheMovingDeviceIsCancelled() {
        std::unique_ptr<Shell> shell = startOnFake(QStringLiteral("sim:throttle=0,axes=2"));
        QVERIFY(shell);
        DeviceSession* session = shell->session();
        QVERIFY(QTest::qWaitFor([session] { return session->motionStop()->armed(); },
                                kDeviceTimeoutMs));
        QStringList asked;
        session->setLeaveCheck(this, [&asked](const QString& action) {
            asked << action;
            return false;  // the person cancels
        });
        ConnectionPage* page = shell->window()->connectionPage();
        NextDialog<QMessageBox> yes(
            [](QMessageBox* box) { box->button(QMessageBox::Yes)->click(); });
        QSignalSpy started(&session->worker(), &comm::JobRunner::jobStarted);
        page->findChild<QPushButton*>(QStringLiteral("detectButton"))->click();
        QCOMPARE(yes.answered(), 1);
        QCOMPARE(asked, QStringList({QStringLiteral("Disconnect")}));
        // What the click queued (if anything) would have reached the worker by now.
        QTest::qWait(0);
        QCOMPARE(session->state(), comm::ConnectionState::Connected);
        QVERIFY(session->wantsConnection());
        QVERIFY(page->findChild<QLabel*>(QStringLiteral("detectResult"))->text().isEmpty());
        QVERIFY(page->findChild<QPushButton*>(QStringLiteral("detectButton"))->isEnabled());
        for (const QList<QVariant>& job : started)
            QVERIFY2(!job.at(1).toString().startsWith(QLatin1String("Detect")),
                     qPrintable(job.at(1).toString()));
    }
};

QTEST_MAIN(TestDetect)
#include "tst_detect.moc"
