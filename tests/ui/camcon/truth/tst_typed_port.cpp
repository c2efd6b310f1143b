// Issue 12, points 6 and 3: a port is typed as a person types it (a pty, a
// tcp:// device server), Enter, Connect; the GUI connects there and shows
// that device. A connect that fails is said on screen, not on stderr.
#include "pty_simulator.h"

#include "comm/sim/sim_pacer.h"
#include "comm/sim/sim_tcp_server.h"
#include "ui/connection_page.h"
#include "ui/connection_status.h"
#include "ui/device_session.h"
#include "ui/language.h"

#include <QComboBox>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QtTest>

using namespace cambench;
using namespace cambench::test;

namespace {

QComboBox* portBox(ConnectionPage* page) {
    for (QComboBox* box : page->findChildren<QComboBox*>()) {
        if (box->isEditable()) return box;
    }
    return nullptr;
}

QPushButton* connectButton(ConnectionPage* page) {
    for (QPushButton* button : page->findChildren<QPushButton*>()) {
        if (button->text() == QLatin1String("Connect") ||
            button->text() == QLatin1String("Reconnect"))
            return button;
    }
    return nullptr;
}

// Selects the port box's text and types `port`.
bool typePort(Shell& shell, const QString& port) {
    shell.window()->showSection(MainWindow::Connection);
    QComboBox* box = portBox(shell.window()->connectionPage());
    if (!box) return false;
    box->lineEdit()->selectAll();
    QTest::keyClick(box->lineEdit(), Qt::Key_Backspace);
    QTest::keyClicks(box->lineEdit(), port);
    return true;
}

// Types `port` and presses Enter: that connects (issue 28, point 5).
bool typeAndConnect(Shell& shell, const QString& port) {
    if (!typePort(shell, port)) return false;
    QTest::keyClick(portBox(shell.window()->connectionPage())->lineEdit(), Qt::Key_Return);
    return true;
}

// The connect the click started has reached a device and identified it
// (not the connection that was there before the click).
bool connectedAndChecked(Shell& shell, const QString& port) {
    // The banner names a device only once it has identified itself.
    auto* strip = shell.window()->findChild<ConnectionStrip*>();
    const QString connected = QStringLiteral("Connected to %1: CamCon").arg(port);
    return QTest::qWaitFor([strip, connected] { return strip->text().startsWith(connected); },
                           kDeviceTimeoutMs);
}

}  // namespace

class TypedPortTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        useTestSettings();
        QVERIFY(setLanguage(QStringLiteral("en")));
    }
    void typedPtyConnectsAndShowsThatDevice();
    void typedDeviceServerAddressConnects();
    void failedConnectIsSaidOnScreen();
    void simulatedDeviceIsSaidOnTheConnectionPage();
    void theButtonSaysConnectForAnotherPort();
    void disconnectStopsTheRetries();
};

void TypedPortTest::typedPtyConnectsAndShowsThatDevice() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    PtySimulator other;
    QVERIFY(other.isOpen());
    QVERIFY(typeAndConnect(*shell, other.path()));
    QVERIFY(connectedAndChecked(*shell, other.path()));
    QCOMPARE(shell->session()->connection().port, other.path());
    auto* strip = shell->window()->findChild<ConnectionStrip*>();
    QVERIFY2(strip->text().contains(other.path()), qPrintable(strip->text()));
}

void TypedPortTest::typedDeviceServerAddressConnects() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    comm::SimPortConfig config;
    std::unique_ptr<comm::SimLine> line = comm::makeSimLine(config);
    comm::SimPacer pacer(config.baud, false);
    comm::SimTcpServer server(*line, pacer);
    QVERIFY(server.listen(0).ok());
    const QString address = QStringLiteral("tcp://127.0.0.1:%1").arg(server.port());
    QVERIFY(typeAndConnect(*shell, address));
    QVERIFY(connectedAndChecked(*shell, address));
    QCOMPARE(shell->session()->connection().port, address);
}

void TypedPortTest::failedConnectIsSaidOnScreen() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    const QString port = QStringLiteral("/dev/cambench-no-such-port");
    QVERIFY(typeAndConnect(*shell, port));
    auto* failure =
        shell->window()->connectionPage()->findChild<QLabel*>(QStringLiteral("connectFailure"));
    QVERIFY(failure);
    QTRY_VERIFY_WITH_TIMEOUT(failure->isVisible(), kDeviceTimeoutMs);
    QVERIFY2(failure->text().contains(port), qPrintable(failure->text()));
    QVERIFY2(failure->text().contains(QLatin1String("Check")), qPrintable(failure->text()));
    auto* strip = shell->window()->findChild<ConnectionStrip*>();
    QVERIFY(strip->isAlarm());
    QVERIFY2(strip->text().startsWith(QStringLiteral("Not connected to %1").arg(port)),
             qPrintable(strip->text()));
    // The panel no longer presents the last device as the one on this port.
    QGroupBox* identity = nullptr;
    for (QGroupBox* box : shell->window()->connectionPage()->findChildren<QGroupBox*>()) {
        if (box->title() == QLatin1String("Device")) identity = box;
    }
    QVERIFY(identity);
    // The CamCon's panel in the box: greyed.
    QWidget* panel = nullptr;
    for (QWidget* child : identity->findChildren<QWidget*>(Qt::FindDirectChildrenOnly))
        if (child->isVisibleTo(identity)) panel = child;
    QVERIFY(panel);
    QVERIFY(!panel->isEnabled());
    bool lastSaid = false;
    for (QLabel* label : identity->findChildren<QLabel*>())
        lastSaid = lastSaid || label->text().startsWith(QLatin1String("Last connected: CamCon"));
    QVERIFY(lastSaid);
}

void TypedPortTest::simulatedDeviceIsSaidOnTheConnectionPage() {
    // The first start: the demo device, and a word that it is one (point 8).
    auto shell = startOnSimulator();
    QVERIFY(shell);
    shell->window()->show();
    shell->window()->showSection(MainWindow::Connection);
    auto* note =
        shell->window()->connectionPage()->findChild<QLabel*>(QStringLiteral("simulatedNote"));
    QVERIFY(note);
    QVERIFY(note->isVisible());
    QVERIFY2(note->text().contains(QLatin1String("simulated demo device")),
             qPrintable(note->text()));
    PtySimulator other;
    QVERIFY(typeAndConnect(*shell, other.path()));
    QVERIFY(connectedAndChecked(*shell, other.path()));
    QVERIFY(!note->isVisible());
}

void TypedPortTest::theButtonSaysConnectForAnotherPort() {
    PtySimulator first;
    auto shell = startOnPty(first);
    QVERIFY(shell);
    ConnectionPage* page = shell->window()->connectionPage();
    QVERIFY(typePort(*shell, first.path()));
    QCOMPARE(connectButton(page)->text(), QStringLiteral("Reconnect"));
    PtySimulator other;
    QVERIFY(typePort(*shell, other.path()));
    QCOMPARE(connectButton(page)->text(), QStringLiteral("Connect"));
    // Scan bus is not offered on a point-to-point line.
    QPushButton* scan = nullptr;
    for (QPushButton* button : page->findChildren<QPushButton*>())
        if (button->text() == QLatin1String("Scan bus")) scan = button;
    QVERIFY(scan);
    QVERIFY(!scan->isVisibleTo(page));
}

void TypedPortTest::disconnectStopsTheRetries() {
    auto sim = std::make_unique<PtySimulator>();
    auto shell = startOnPty(*sim);
    QVERIFY(shell);
    shell->session()->setRetryInterval(100);
    sim->stop();
    QTRY_VERIFY_WITH_TIMEOUT(shell->session()->isRetrying(), kDeviceTimeoutMs);
    QPushButton* disconnect = nullptr;
    for (QPushButton* button : shell->window()->connectionPage()->findChildren<QPushButton*>())
        if (button->text() == QLatin1String("Disconnect")) disconnect = button;
    QVERIFY(disconnect);
    QTRY_VERIFY_WITH_TIMEOUT(disconnect->isEnabled(), kDeviceTimeoutMs);
    QTest::mouseClick(disconnect, Qt::LeftButton);
    QVERIFY(!shell->session()->isRetrying());
    QVERIFY(!shell->session()->wantsConnection());
}

QTEST_MAIN(TypedPortTest)
#include "tst_typed_port.moc"
