// The smaller faults of issue 6, each as a person would meet it: menu
// texts and shortcuts, a dead-time cell that lost a digit, the connection
// strip, PLC operands, status messages, the project's name after a language
// switch, the tool bars at 1280 px, and the error dialog's height.
#include "shell_fixture.h"

#include "ui/camcon/cam_page.h"
#include "ui/camcon/cameditor/cam_editor_widget.h"
#include "ui/camcon/cameditor/range_delegate.h"
#include "ui/camcon/dead_times_model.h"
#include "ui/camcon/dead_times_page.h"
#include "ui/camcon/plc_matrix_model.h"
#include "ui/camcon/plc_page.h"
#include "ui/connection_status.h"
#include "ui/device_session.h"
#include "ui/language.h"
#include "ui/report_dialog.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QMenuBar>
#include <QPushButton>
#include <QScreen>
#include <QStatusBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QToolBar>
#include <QToolButton>
#include <QtTest>
#include "ui/sentence.h"

using namespace cambench;
using namespace cambench::test;

class SmallFaultsTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        useTestSettings();
        QVERIFY(setLanguage(QStringLiteral("en")));
    }
    void viewMenuShowsEncoderAndSystemWithItsAmpersand();
    void ctrlYRedoes();
    void deadTimeCellRefuses1500InsteadOfMaking150();
    void connectionStripKeepsItsHeightAndSpeaksInSentences();
    void plcOperandsI5AndE5AreRefusedWithAReason();
    void progressMessageGoesWhenItsJobIsDone();
    void projectNameSurvivesLanguageSwitch();
    void toolBarsShowEveryActionAt1280Pixels();
    void errorDialogIsNeverTallerThanTheScreen();
    void commandNamesStayOutOfMessagesForPeople();
};

void SmallFaultsTest::viewMenuShowsEncoderAndSystemWithItsAmpersand() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QMenu* view = nullptr;
    for (QAction* action : shell->window()->menuBar()->actions()) {
        if (action->text() == QStringLiteral("&View")) view = action->menu();
    }
    QVERIFY(view);
    QStringList texts;
    for (QAction* action : view->actions()) texts << action->text();
    // "&&" shows as "&": the menu reads "Encoder & system", not "Encoder _system".
    QVERIFY2(texts.contains(QStringLiteral("Encoder && system")),
             qPrintable(texts.join(QLatin1Char('|'))));
}

void SmallFaultsTest::ctrlYRedoes() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QAction* redo = camConWindow(shell->window())->camPage()->editor()->redoAction();
    QVERIFY(redo->shortcuts().contains(QKeySequence(Qt::CTRL | Qt::Key_Y)));
    QVERIFY(redo->shortcuts().contains(QKeySequence(QKeySequence::Redo)));
}

void SmallFaultsTest::deadTimeCellRefuses1500InsteadOfMaking150() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QVERIFY(waitForSections(*shell));
    MainWindow* window = shell->window();
    camConWindow(window)->showSection(CamConWindow::DeadTimes);
    QTableView* view = camConWindow(window)->deadTimesPage()->view();
    const QModelIndex cell =
        camConWindow(window)->deadTimesPage()->model()->index(2, DeadTimesModel::DeadTimeColumn);
    const qint32 before = camConWorkspace(*shell)->cams()->deadTime(3);
    view->setCurrentIndex(cell);
    view->edit(cell);
    auto* editor = qobject_cast<QDoubleSpinBox*>(QApplication::focusWidget());
    QVERIFY(editor);
    editor->selectAll();
    QTest::keyClicks(editor, QStringLiteral("1500"));
    QVERIFY2(editor->cleanText().startsWith(QStringLiteral("1500")),
             qPrintable(editor->cleanText()));
    QTest::keyClick(editor, Qt::Key_Return);
    auto* delegate = qobject_cast<RangeDelegate*>(view->itemDelegate());
    QVERIFY(delegate);
    QVERIFY2(delegate->lastRefusal().contains(QStringLiteral("1500")),
             qPrintable(delegate->lastRefusal()));
    QCOMPARE(camConWorkspace(*shell)->cams()->deadTime(3), before);  // not 150.0 ms
    editor->selectAll();
    QTest::keyClicks(editor, QStringLiteral("150"));
    QTest::keyClick(editor, Qt::Key_Return);
    QTRY_COMPARE(camConWorkspace(*shell)->cams()->deadTime(3), 1500);  // 150.0 ms, in 0.1 ms steps
}

void SmallFaultsTest::connectionStripKeepsItsHeightAndSpeaksInSentences() {
    auto shell = startOnSimulator();
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

void SmallFaultsTest::plcOperandsI5AndE5AreRefusedWithAReason() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    PlcPage* page = camConWindow(shell->window())->plcPage();
    PlcMatrixModel* model = page->model();
    for (const QString& typed : {QStringLiteral("I5"), QStringLiteral("E5")}) {
        QVERIFY(!model->setData(model->index(0, 0), typed));
        QVERIFY2(page->refusalText().contains(typed) &&
                     page->refusalText().contains(QStringLiteral("P5")),
                 qPrintable(page->refusalText()));
    }
    QVERIFY(model->setData(model->index(0, 0), QStringLiteral("P5")));
    QVERIFY(page->refusalText().isEmpty());
}

void SmallFaultsTest::progressMessageGoesWhenItsJobIsDone() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    std::optional<Status> read;
    camConWindow(shell->window())->camPage()->readProgram(1, [&](const Status& s) { read = s; });
    QVERIFY(shell->window()->statusBar()->currentMessage().endsWith(QChar(0x2026)));
    QTRY_VERIFY_WITH_TIMEOUT(read.has_value(), kDeviceTimeoutMs);
    QVERIFY(!shell->window()->statusBar()->currentMessage().endsWith(QChar(0x2026)));
}

void SmallFaultsTest::projectNameSurvivesLanguageSwitch() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("line-7.json"));
    QVERIFY(camConWindow(shell->window())->saveProjectTo(path).ok());
    QVERIFY(shell->window()->windowTitle().contains(QStringLiteral("line-7.json")));
    shell->switchLanguage(QStringLiteral("de"));
    QVERIFY2(shell->window()->windowTitle().contains(QStringLiteral("line-7.json")),
             qPrintable(shell->window()->windowTitle()));
    shell->switchLanguage(QStringLiteral("en"));
    QVERIFY(shell->window()->windowTitle().contains(QStringLiteral("line-7.json")));
}

void SmallFaultsTest::toolBarsShowEveryActionAt1280Pixels() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    MainWindow* window = shell->window();
    for (const QString& language : {QStringLiteral("en"), QStringLiteral("de")}) {
        shell->switchLanguage(language);
        window = shell->window();
        window->showNormal();
        window->resize(1280, 800);
        camConWindow(window)->showSection(CamConWindow::Cams);
        QVERIFY(QTest::qWaitForWindowExposed(window));
        for (QToolBar* bar : camConWindow(window)->camPage()->editor()->findChildren<QToolBar*>()) {
            // The overflow button shows only when actions do not fit.
            for (QToolButton* button :
                 bar->findChildren<QToolButton*>(QStringLiteral("qt_toolbar_ext_button")))
                QVERIFY2(!button->isVisible(), qPrintable(language));
        }
        const QList<QAction*> actions = camConWindow(window)->camPage()->editor()->editorActions();
        for (QAction* zoom : {actions.at(9), actions.at(10), actions.at(11)}) {
            bool shown = false;
            for (QToolButton* button : window->findChildren<QToolButton*>()) {
                if (button->defaultAction() == zoom && button->isVisible()) shown = true;
            }
            QVERIFY2(shown, qPrintable(zoom->text()));
        }
    }
    shell->switchLanguage(QStringLiteral("en"));
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
