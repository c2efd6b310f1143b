// The smaller faults of issue 6 the shell has, each as a person would meet
// it: the connection strip, status messages, the error dialog's height, the
// words of messages. On the test-only fake family (tests/family/); those on
// a family's pages are in its folder (tests/ui/<family>/).
#include "fake_shell_fixture.h"

#include "ui/connection_status.h"
#include "ui/device_session.h"
#include "ui/language.h"
#include "ui/report_dialog.h"
#include "ui/sentence.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QPushButton>
#include <QScreen>
#include <QStatusBar>
#include <QtTest>

using namespace cambench;
using namespace cambench::test;

class SmallFaultsTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { QVERIFY(setUpWithTheFakeFamily()); }
    void connectionStripKeepsItsHeightAndSpeaksInSentences();
    void progressMessageGoesWhenItsJobIsDone();
    void errorDialogIsNeverTallerThanTheScreen();
    void commandNamesStayOutOfMessagesForPeople();
};

void SmallFaultsTest::connectionStripKeepsItsHeightAndSpeaksInSentences() {
    auto shell = startOnFake();
    QVERIFY(shell);
    ConnectionStrip* strip = shell->window()->connectionStrip();
    const int height = strip->height();
    QVERIFY(!strip->isAlarm());
    // The line goes away: same height, and the message ends its sentence.
    DeviceSession* session = shell->session();
    comm::ConnectionSettings gone;
    gone.port = QStringLiteral("/dev/cambench-no-such-port");
    session->connectTo(gone, session->protocolSettings());
    QTRY_VERIFY_WITH_TIMEOUT(session->state() == comm::ConnectionState::Disconnected,
                             kDeviceTimeoutMs);
    QCOMPARE(strip->height(), height);
    shell->window()->showSection(MainWindow::Connection);
    QCOMPARE(strip->height(), height);
    const QString text = strip->text();
    QVERIFY2(!text.contains(QRegularExpression(QStringLiteral("[a-z] [A-Z][a-z]+ retries"))),
             qPrintable(text));
    QVERIFY2(asSentence(QStringLiteral("no reply")) == QStringLiteral("no reply."),
             "a sentence ends with a stop");
    QCOMPARE(asSentence(QStringLiteral("Done.")), QStringLiteral("Done."));
}

void SmallFaultsTest::progressMessageGoesWhenItsJobIsDone() {
    auto shell = startOnFake();
    QVERIFY(shell);
    auto* page = shell->window()->findChild<QWidget*>(QStringLiteral("fakePage"));
    QVERIFY(page);
    page->findChild<QPushButton*>(QStringLiteral("fakePing"))->click();
    QVERIFY(shell->window()->statusBar()->currentMessage().endsWith(QChar(0x2026)));
    auto* answer = page->findChild<QLabel*>(QStringLiteral("fakeAnswer"));
    QTRY_COMPARE_WITH_TIMEOUT(answer->text(), QStringLiteral("PONG 7"), kDeviceTimeoutMs);
    QVERIFY(!shell->window()->statusBar()->currentMessage().endsWith(QChar(0x2026)));
}

void SmallFaultsTest::errorDialogIsNeverTallerThanTheScreen() {
    QStringList lines;
    for (int output = 1; output <= 96; ++output)
        lines << QStringLiteral(
                     "program 0, output %1: failed: the device reported error -1; the device keeps "
                     "no cams")
                     .arg(output);
    ReportDialog dialog(QMessageBox::Warning, QStringLiteral("Write program 0"),
                        QStringLiteral("96 failed"), lines.join(QLatin1Char('\n')));
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    const QRect screen = dialog.screen()->availableGeometry();
    QVERIFY2(dialog.frameGeometry().height() <= screen.height(),
             qPrintable(QString::number(dialog.height())));
    QPushButton* ok = dialog.buttons()->button(QDialogButtonBox::Ok);
    QVERIFY(ok->isVisible());
    QVERIFY(dialog.rect().contains(QRect(ok->mapTo(&dialog, QPoint(0, 0)), ok->size())));
    QCOMPARE(dialog.details().count(QLatin1Char('\n')), 95);  // every line, in a scrolling box
}

void SmallFaultsTest::commandNamesStayOutOfMessagesForPeople() {
    // Issue 12, point 8: the words say it; "?EPROM" is for the CLI's log.
    QCOMPARE(withoutCommandNames(QStringLiteral(
                 "reading the device identity (?EPROM): no reply from the device to ?EPROM on "
                 "/dev/ttyUSB0 after 2 attempts")),
             QStringLiteral("reading the device identity: no reply from the device on "
                            "/dev/ttyUSB0 after 2 attempts"));
    QCOMPARE(withoutCommandNames(QStringLiteral("Is it on? Yes (really).")),
             QStringLiteral("Is it on? Yes (really)."));
}

QTEST_MAIN(SmallFaultsTest)
#include "tst_small_faults.moc"
