// The smaller faults of issue 6 on the CamCon's pages, each as a person
// would meet it: menu texts and shortcuts, a dead-time cell that lost a
// digit, PLC operands, the project's name after a language switch, the
// cam editor's tool bars at 1280 px.
#include "camcon_fixture.h"

#include "ui/camcon/cam_page.h"
#include "ui/camcon/cameditor/cam_editor_widget.h"
#include "ui/camcon/cameditor/range_delegate.h"
#include "ui/camcon/dead_times_model.h"
#include "ui/camcon/dead_times_page.h"
#include "ui/camcon/plc_matrix_model.h"
#include "ui/camcon/plc_page.h"
#include "ui/language.h"

#include <QDoubleSpinBox>
#include <QMenuBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QToolBar>
#include <QToolButton>
#include <QtTest>

using namespace cambench;
using namespace cambench::test;

class CamConSmallFaultsTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        useTestSettings();
        QVERIFY(setLanguage(QStringLiteral("en")));
    }
    void viewMenuShowsEncoderAndSystemWithItsAmpersand();
    void ctrlYRedoes();
    void deadTimeCellRefuses1500InsteadOfMaking150();
    void plcOperandsI5AndE5AreRefusedWithAReason();
    void projectNameSurvivesLanguageSwitch();
    void toolBarsShowEveryActionAt1280Pixels();
};

void CamConSmallFaultsTest::viewMenuShowsEncoderAndSystemWithItsAmpersand() {
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

void CamConSmallFaultsTest::ctrlYRedoes() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QAction* redo = camConWindow(shell->window())->camPage()->editor()->redoAction();
    QVERIFY(redo->shortcuts().contains(QKeySequence(Qt::CTRL | Qt::Key_Y)));
    QVERIFY(redo->shortcuts().contains(QKeySequence(QKeySequence::Redo)));
}

void CamConSmallFaultsTest::deadTimeCellRefuses1500InsteadOfMaking150() {
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

void CamConSmallFaultsTest::plcOperandsI5AndE5AreRefusedWithAReason() {
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

void CamConSmallFaultsTest::projectNameSurvivesLanguageSwitch() {
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

void CamConSmallFaultsTest::toolBarsShowEveryActionAt1280Pixels() {
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

QTEST_MAIN(CamConSmallFaultsTest)
#include "tst_camcon_small_faults.moc"
