// Issue 27 on the MC-1 Axes page: the axes the controller has are found and
// offered, values read through CamBench's guessed parameter numbers are
// marked provisional, an acknowledged move whose read-back is refused says
// both (done, and why reading back failed), the controller's own parameter
// table is loaded from a file (and remembered), a malformed one is refused
// naming its line. Against a simulated MC200 V2 with axes 1, 2 and 5 whose
// parameter numbers are not the guess.
#include "../shell/shell_fixture.h"

#include "ui/mc1/mc1_axes_page.h"
#include "ui/mc1/mc1_axis_parameters_box.h"
#include "ui/mc1/mc1_window.h"
#include "ui/mc1/protocols/mc1_settings_widget.h"

#include "comm/mc1/mc1_protocol.h"

#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTemporaryDir>

using namespace cambench;
using namespace cambench::test;

namespace {

bool writeFile(const QString& path, const QByteArray& text) {
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(text) == text.size();
}

}  // namespace

class Mc1AxesParametersTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { useTestSettings(); }

    void provisionalUntilTheControllersTableIsLoaded() {
        std::unique_ptr<Shell> shell =
            startOnSimulator(QStringLiteral("sim:variant=mc200v2;axes=1,2,5;parameters=0x2000"),
                             QStringLiteral("mc1"));
        QVERIFY(shell);
        Mc1AxesPage* page = mc1Window(shell->window())->axesPage();
        shell->window()->showPage(page);
        QVERIFY(QTest::qWaitFor(
            [&] { return page->axesLabel()->text().contains(QLatin1String("Axes 1, 2, 5")); },
            kDeviceTimeoutMs));
        QVERIFY2(page->axesLabel()->text().contains(QLatin1String("RDTABLE")),
                 qPrintable(page->axesLabel()->text()));
        QCOMPARE(page->findChild<QSpinBox*>(QStringLiteral("mc1Axis"))->maximum(), 5);
        QLabel* source = page->parametersBox()->sourceLabel();
        QVERIFY2(source->text().contains(QLatin1String("provisional")), qPrintable(source->text()));

        // A move the controller acknowledges; its read-back through the
        // guess is refused: both are said.
        QLabel* result = page->findChild<QLabel*>(QStringLiteral("pageResult"));
        {
            auto yes = answerConfirmation(true);
            page->command(comm::Mc1AxisCommand::MoveRelative, 100);
            QVERIFY(
                QTest::qWaitFor([&] { return result->text().startsWith(QLatin1String("Done")); },
                                kDeviceTimeoutMs));
        }
        QVERIFY2(result->text().contains(QLatin1String("acknowledged")),
                 qPrintable(result->text()));
        QVERIFY2(result->text().contains(QLatin1String("Reading back failed")),
                 qPrintable(result->text()));
        QVERIFY2(result->text().contains(QLatin1String("load the controller's parameter table")),
                 qPrintable(result->text()));

        // A malformed file: refused naming its line, the guess stays.
        QTemporaryDir dir;
        const QString bad = dir.filePath(QStringLiteral("bad.csv"));
        QVERIFY(writeFile(bad, "position,1,0x2010\nposition,1\n"));
        QString warned;
        NextDialog<QMessageBox> warning([&warned](QMessageBox* box) {
            warned = box->text();
            box->buttons().first()->click();
        });
        QVERIFY(!page->parametersBox()->load(bad));
        QVERIFY2(warned.contains(QLatin1String("line 2")), qPrintable(warned));
        QVERIFY(page->parametersBox()->table().provisional);

        // The controller's own table: read, not provisional, remembered.
        const QString good = dir.filePath(QStringLiteral("mc200.csv"));
        QVERIFY(writeFile(good,
                          "name,axis,parameter\nposition,1,0x2010\ntarget,1,0x2011\n"
                          "status,1,0x2012\n"));
        QVERIFY(page->parametersBox()->load(good));
        QVERIFY2(source->text().contains(good), qPrintable(source->text()));
        QVERIFY(QTest::qWaitFor(
            [&] {
                return page->stateLabel()->text().contains(QLatin1String("axis 1 stands at 100"));
            },
            kDeviceTimeoutMs));
        QVERIFY2(!page->stateLabel()->text().contains(QLatin1String("provisional")),
                 qPrintable(page->stateLabel()->text()));
        QCOMPARE(QSettings().value(QStringLiteral("mc1/axisParameterTable")).toString(), good);
    }

    // The connection page's axes: empty finds them, "1,2" names them.
    void theConnectionNamesTheAxesOrLeavesThemToBeFound() {
        Mc1SettingsWidget widget;
        comm::Mc1ProtocolSettings settings;
        widget.load(settings);
        QCOMPARE(widget.axes()->text(), QString());
        QTest::keyClicks(widget.axes(), QStringLiteral("1,9x2"));  // 9 and x are not taken
        QCOMPARE(widget.axes()->text(), QStringLiteral("1,2"));
        widget.store(settings);
        QCOMPARE(settings.mc1.axes, std::optional<QList<int>>(QList<int>{1, 2}));
        widget.axes()->clear();
        widget.store(settings);
        QVERIFY(!settings.mc1.axes);
    }
};

QTEST_MAIN(Mc1AxesParametersTest)
#include "tst_mc1_axes_parameters.moc"
