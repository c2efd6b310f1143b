// Issue 15: the Compax3 pages on real widgets against the simulated drive
// through the real worker: the objects with their values, an edit checked
// at once and written only after Yes (what fails stays typed in), the
// status lamps, motion only after a confirmation, STOP and Escape, the
// watch list with its trend, the parameter file compared and written back,
// and a lost line making the values stale; the pages on the shell's poll
// cycle (paused behind a backup) and a read a STOP dropped (issue 27).
#include "../shell/shell_fixture.h"

#include "ui/compax3/compax3_gui.h"
#include "ui/compax3/compax3_motion_page.h"
#include "ui/compax3/compax3_object_model.h"
#include "ui/compax3/compax3_objects_page.h"
#include "ui/compax3/compax3_parameters_page.h"
#include "ui/compax3/compax3_status_page.h"
#include "ui/compax3/compax3_watch_page.h"
#include "ui/compax3/compax3_window.h"
#include "ui/device_session.h"
#include "ui/live_freshness.h"
#include "ui/live_poll_cycle.h"
#include "ui/motion_stop.h"
#include "ui/multi_trend_chart.h"
#include "ui/report_dialog.h"

#include "comm/compax3/compax3_drive.h"
#include "comm/compax3/compax3_objects.h"
#include "comm/sim/compax3/sim_compax3_line.h"
#include "comm/sim/sim_transport.h"
#include "comm/worker/guarded_transport.h"
#include "model/compax3/compax3_parameter_file.h"

#include <QApplication>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QScopeGuard>
#include <QSemaphore>
#include <QSignalSpy>
#include <QSortFilterProxyModel>
#include <QSpinBox>
#include <QTableWidget>
#include <QTimer>
#include "ui/connection_page.h"

#include <QListWidget>
#include <QTemporaryDir>
#include <QTreeView>

using namespace cambench;
using namespace cambench::test;

namespace {

std::unique_ptr<Shell> startCompax3() {
    return startOnSimulator(QStringLiteral("sim"), QStringLiteral("compax3"));
}

QString resultOf(QWidget* page) {
    return page->findChild<QLabel*>(QStringLiteral("pageResult"))->text();
}

// The Status page's lamp of `bit` drawn grey (not live).
bool lampGrey(QWidget* page, int bit) {
    return page->findChild<QLabel*>(QStringLiteral("compax3Bit%1").arg(bit))
        ->text()
        .contains(QLatin1String("color:gray"));
}

// The confirmation's action: the first button that is not Cancel.
void answerYes(QMessageBox* box) {
    for (QAbstractButton* button : box->buttons())
        if (box->buttonRole(button) != QMessageBox::RejectRole) {
            button->click();
            return;
        }
}

bool jobStarted(const QSignalSpy& started, const QString& title) {
    for (const QList<QVariant>& job : started)
        if (job.at(1).toString() == title) return true;
    return false;
}

// Answers the message boxes that come up, one after the other, Yes (the
// action) or Cancel as `answers` says, and keeps what each asked.
class AnswerEach : public QObject {
public:
    explicit AnswerEach(QList<bool> answers) : m_answers(std::move(answers)) {
        m_timer.setInterval(10);
        connect(&m_timer, &QTimer::timeout, this, [this] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!box || box == m_last || m_answers.isEmpty()) return;
            m_last = box;
            asked << box->text() + QLatin1Char('\n') + box->informativeText();
            const bool yes = m_answers.takeFirst();
            for (QAbstractButton* button : box->buttons())
                if ((box->buttonRole(button) == QMessageBox::RejectRole) != yes) {
                    button->click();
                    return;
                }
        });
        m_timer.start();
    }
    QStringList asked;

private:
    QList<bool> m_answers;
    QPointer<QMessageBox> m_last;
    QTimer m_timer;
};

// The simulated drive behind the session answers every request `ms` late
// from now on (its line, reached through the worker).
void delayDriveAnswers(DeviceSession* session, int ms) {
    QSemaphore done;
    bool found = false;
    session->worker().submit(
        comm::JobPriority::User, QStringLiteral("slow drive"),
        [&done, &found, ms](comm::JobContext& job) {
            // The worker's transport guards the simulated one.
            auto* drive = dynamic_cast<comm::Compax3Drive*>(job.device());
            auto* guarded =
                drive ? dynamic_cast<comm::GuardedTransport*>(&drive->engine().transport())
                      : nullptr;
            auto* sim = guarded ? dynamic_cast<comm::SimTransport*>(guarded->connected()) : nullptr;
            auto* line = sim ? dynamic_cast<comm::SimCompax3Line*>(&sim->line()) : nullptr;
            if (line) line->delayAnswers(ms);
            found = line != nullptr;
            done.release();
        });
    QVERIFY(QTest::qWaitFor([&done] { return done.tryAcquire(); }, kDeviceTimeoutMs));
    QVERIFY(found);
}

// `page` set to RS485 and the simulated drive at address 7, with `typed`
// as the address to connect to.
void showRs485DriveAt7(ConnectionPage* page, int typed) {
    page->setPort(QStringLiteral("sim:address=7"));
    page->setProtocol(QStringLiteral("compax3-rs485"));
    std::unique_ptr<comm::ProtocolSettings> settings = page->protocolSettings()->clone();
    settings->setDevice(typed);
    page->showConnection(page->connectionSettings(), *settings);
}

// The Motion page of `shell`'s drive shown and the drive enabled (the
// confirmation answered Yes); nullptr when that fails.
Compax3MotionPage* enabledMotionPage(const std::unique_ptr<Shell>& shell) {
    if (!shell) return nullptr;
    Compax3MotionPage* motion = compax3Window(shell->window())->motionPage();
    shell->window()->showPage(motion);
    // The page's first read done: a motion is never queued behind a job
    // (issue 35), so one asked while the page reads is refused.
    if (!QTest::qWaitFor([&] { return motion->axisText().startsWith(QLatin1String("Powerless")); },
                         kDeviceTimeoutMs))
        return nullptr;
    QTest::qWait(200);
    auto yes = answerConfirmation(true);
    motion->runMotion(comm::Compax3Motion::Enable);
    const bool powered = QTest::qWaitFor(
        [&] { return motion->axisText().startsWith(QLatin1String("Powered")); }, kDeviceTimeoutMs);
    return powered ? motion : nullptr;
}

}  // namespace

class Compax3PagesTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { useTestSettings(); }

    // On RS485 a drive is known by its address (the number set on the
    // drive): the scan list says "address", not the CamCon's "device number".
    void busScanListsDrivesByAddress() {
        std::unique_ptr<Shell> shell = startCompax3();
        QVERIFY(shell);
        ConnectionPage* page = shell->window()->connectionPage();
        showRs485DriveAt7(page, 7);
        QSignalSpy loaded(shell->window(), &MainWindow::loaded);
        auto leave = answerLeaveQuestion();
        shell->window()->connectAndLoad();
        QVERIFY(loaded.wait(kDeviceTimeoutMs));
        QVERIFY(loaded.first().first().toBool());
        auto* devices = page->findChild<QListWidget*>();
        QVERIFY(devices);
        page->scanBus();
        QVERIFY(QTest::qWaitFor([&] { return devices->count() > 0; }, 4 * kDeviceTimeoutMs));
        for (int row = 0; row < devices->count(); ++row) {
            const QString text = devices->item(row)->text();
            QVERIFY2(text.contains(QLatin1String(", address ")), qPrintable(text));
            QVERIFY2(!text.contains(QLatin1String("device number")), qPrintable(text));
        }
    }

    // A drive that does not answer at the address typed is looked for on
    // the bus; the one found is the one CamBench then talks to, and the
    // page says so: its field shows that address and it does not ask for a
    // reconnect to reach the drive it already reaches.
    void aDriveFoundAtAnotherAddressIsTheOneShown() {
        std::unique_ptr<Shell> shell = startCompax3();
        QVERIFY(shell);
        ConnectionPage* page = shell->window()->connectionPage();
        showRs485DriveAt7(page, 0);
        auto leave = answerLeaveQuestion();
        shell->window()->connectAndLoad();
        DeviceSession* session = shell->window()->session();
        QVERIFY(QTest::qWaitFor([&] { return session->protocol().device() == 7; },
                                4 * kDeviceTimeoutMs));
        QCOMPARE(page->protocolSettings()->device(), 7);
        for (const QLabel* label : page->findChildren<QLabel*>()) {
            if (label->text().startsWith(QLatin1String("Reconnect to reach")))
                QVERIFY2(label->isHidden(), qPrintable(label->text()));
        }
    }

    void objectsShowTheDriveAndWriteOnlyAfterYes() {
        std::unique_ptr<Shell> shell = startCompax3();
        QVERIFY(shell);
        Compax3Window* c3 = compax3Window(shell->window());
        QVERIFY(c3);
        QVERIFY(c3->facts().known);
        QCOMPARE(c3->facts().identity.type(), QStringLiteral("S025V2"));
        Compax3ObjectsPage* objects = c3->objectsPage();
        shell->window()->showPage(objects);
        Compax3ObjectModel* model = objects->model();
        const Compax3ObjectId target = comm::compax3SetTarget(2);
        QVERIFY(QTest::qWaitFor([&] { return model->driveValue(target).has_value(); },
                                kDeviceTimeoutMs));
        QCOMPARE(*model->driveValue(target), QStringLiteral("200"));

        // Typed in: checked at once; a German comma is refused with the fix.
        QVERIFY(model->setData(model->indexOf(target, Compax3ObjectModel::NewValue),
                               QStringLiteral("12,5")));
        QVERIFY(model->edits().isEmpty());
        QVERIFY2(resultOf(objects).contains(QLatin1String("decimal point")),
                 qPrintable(resultOf(objects)));
        QVERIFY(model->setData(model->indexOf(target, Compax3ObjectModel::NewValue),
                               QStringLiteral("12.5")));
        QCOMPARE(model->edits().size(), 1);
        QVERIFY(model->indexOf(target, Compax3ObjectModel::Object)
                    .data()
                    .toString()
                    .startsWith(QStringLiteral("● ")));
        {
            auto no = answerConfirmation(false);
            objects->writeChanges();
            QCOMPARE(no->answered(), 1);
        }
        QCOMPARE(model->edits().size(), 1);
        auto yes = answerConfirmation(true);
        objects->writeChanges();
        QVERIFY(QTest::qWaitFor([&] { return model->edits().isEmpty(); }, kDeviceTimeoutMs));
        QCOMPARE(*model->driveValue(target), QStringLiteral("12.5"));
        QVERIFY2(resultOf(objects).contains(QLatin1String("1 written")),
                 qPrintable(resultOf(objects)));

        // A write the drive refuses (a dictionary of our own allows 7 for a
        // mode; the drive does not): the value stays typed in, the report says
        // it failed, and the drive's value is read again.
        {
            QTemporaryDir dir;
            const QString path = dir.filePath(QStringLiteral("wide.json"));
            QFile file(path);
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write(R"({"format":"cambench-compax3-dictionary","version":1,"objects":[
{"object":"1905.1","name":"Set 1 mode","type":"integer","access":"rw","min":0,"max":9}]})");
            file.close();
            objects->loadDictionary(path);
            const Compax3ObjectId mode = comm::compax3SetMode(1);
            QVERIFY(QTest::qWaitFor([&] { return model->driveValue(mode).has_value(); },
                                    kDeviceTimeoutMs));
            QVERIFY(model->setEdit(mode, QStringLiteral("7")).ok());
            auto write = answerConfirmation(true);
            QString report;
            NextDialog<ReportDialog> close([&report](ReportDialog* dialog) {
                report = dialog->summary();
                dialog->accept();
            });
            objects->writeChanges();
            QVERIFY(QTest::qWaitFor([&] { return !report.isEmpty(); }, kDeviceTimeoutMs));
            QVERIFY2(report.contains(QLatin1String("1 failed")), qPrintable(report));
            QCOMPARE(model->edits().size(), 1);
            QCOMPARE(*model->driveValue(mode), QStringLiteral("1"));
            static_cast<Compax3Gui*>(c3->gui())->setDictionary(Compax3Dictionary::builtin());
        }

        // Any object by number: one the drive lacks is "not on this drive", with
        // the drive's answer.
        objects->readRaw(QStringLiteral("O 4321,1"));
        QVERIFY(QTest::qWaitFor(
            [&] {
                return model->indexOf({4321, 1}, Compax3ObjectModel::DriveValue)
                           .data()
                           .toString() == QLatin1String("not on this drive");
            },
            kDeviceTimeoutMs));
        QVERIFY(model->indexOf({4321, 1}, Compax3ObjectModel::DriveValue)
                    .data(Qt::ToolTipRole)
                    .toString()
                    .contains(QLatin1String("!0002")));

        // The line goes: values stay, marked stale.
        auto leave = answerLeaveQuestion();
        shell->session()->disconnectFromDevice();
        QVERIFY(QTest::qWaitFor(
            [&] {
                return model->indexOf(target, Compax3ObjectModel::DriveValue)
                    .data(Qt::ToolTipRole)
                    .toString()
                    .startsWith(QLatin1String("Stale"));
            },
            kDeviceTimeoutMs));
    }

    void statusAndMotionWithStopAndEscape() {
        std::unique_ptr<Shell> shell = startCompax3();
        QVERIFY(shell);
        Compax3Window* c3 = compax3Window(shell->window());
        Compax3StatusPage* status = c3->statusPage();
        shell->window()->showPage(status);
        QVERIFY(QTest::qWaitFor([&] { return !status->errorText().isEmpty(); }, kDeviceTimeoutMs));
        QCOMPARE(status->errorText(), QStringLiteral("no error"));
        QVERIFY(status->bitOn(10));  // b10 powerless

        Compax3MotionPage* motion = c3->motionPage();
        shell->window()->showPage(motion);
        shell->window()->show();
        shell->window()->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(shell->window()));
        QVERIFY(motion->stopButton()->isVisible());
        {
            auto yes = answerConfirmation(true);
            motion->runMotion(comm::Compax3Motion::Enable);
            QVERIFY(QTest::qWaitFor(
                [&] { return motion->axisText().startsWith(QLatin1String("Powered")); },
                kDeviceTimeoutMs));
        }
        for (bool escape : {false, true}) {
            {
                auto yes = answerConfirmation(true);
                motion->runMotion(comm::Compax3Motion::JogPlus);
                QVERIFY(QTest::qWaitFor(
                    [&] { return motion->axisText().startsWith(QLatin1String("Moving")); },
                    kDeviceTimeoutMs));
            }
            if (escape) {
                shell->window()->activateWindow();
                QVERIFY(QTest::qWaitForWindowActive(shell->window()));
                QTest::keyClick(motion->stopButton(), Qt::Key_Escape);
            } else {
                motion->stopButton()->click();
            }
            QVERIFY2(
                QTest::qWaitFor(
                    [&] {
                        return motion->axisText().startsWith(QLatin1String("Powered, standing"));
                    },
                    kDeviceTimeoutMs),
                qPrintable(motion->axisText() + QLatin1String(" / ") + resultOf(motion)));
        }
        // A motion the user does not confirm is never sent.
        auto no = answerConfirmation(false);
        motion->runMotion(comm::Compax3Motion::JogMinus);
        QTest::qWait(700);
        QVERIFY(motion->axisText().startsWith(QLatin1String("Powered, standing")));
    }

    void anOpenEditorSurvivesAReadAndAPoll() {
        // Issue 27 item 5: what is typed stays typed while values come in.
        std::unique_ptr<Shell> shell = startCompax3();
        QVERIFY(shell);
        Compax3Window* c3 = compax3Window(shell->window());
        Compax3ObjectsPage* objects = c3->objectsPage();
        shell->window()->showPage(objects);
        shell->window()->show();
        Compax3ObjectModel* model = objects->model();
        const Compax3ObjectId target = comm::compax3SetTarget(4);
        QVERIFY(QTest::qWaitFor([&] { return model->driveValue(target).has_value(); },
                                kDeviceTimeoutMs));
        auto* proxy = qobject_cast<QSortFilterProxyModel*>(objects->tree()->model());
        QVERIFY(proxy);
        const QModelIndex cell =
            proxy->mapFromSource(model->indexOf(target, Compax3ObjectModel::NewValue));
        objects->tree()->scrollTo(cell);
        objects->tree()->edit(cell);
        auto* editor = objects->tree()->viewport()->findChild<QLineEdit*>();
        QVERIFY(editor);
        editor->setText(QStringLiteral("400"));
        // The drive's values arrive (a read as after another page's write).
        objects->read({target, comm::compax3SetVelocity(4)});
        QVERIFY(QTest::qWaitFor(
            [&] { return resultOf(objects).startsWith(QLatin1String("Read 2 object")); },
            kDeviceTimeoutMs));
        QCOMPARE(editor->text(), QStringLiteral("400"));
        QVERIFY(model->edits().isEmpty());  // not taken before the person is done

        // The Watch page: its polls never touch what is being typed.
        Compax3WatchPage* watch = c3->watchPage();
        shell->window()->showPage(watch);
        auto* add = watch->findChild<QLineEdit*>(QStringLiteral("compax3WatchAdd"));
        add->setText(QStringLiteral("1901."));
        const int before = watch->chart()->pointCount();
        QVERIFY(QTest::qWaitFor([&] { return watch->chart()->pointCount() >= before + 2; },
                                kDeviceTimeoutMs));
        QCOMPARE(add->text(), QStringLiteral("1901."));
    }

    void aSetStartShowsTheSetAndAWriteShowsOnObjects() {
        // Issue 27 items 4 and 5: the set as the drive holds it, only what
        // was changed written and named, and the Objects page shows it.
        std::unique_ptr<Shell> shell = startCompax3();
        QVERIFY(shell);
        Compax3Window* c3 = compax3Window(shell->window());
        Compax3ObjectModel* model = c3->objectsPage()->model();
        const Compax3ObjectId velocity = comm::compax3SetVelocity(3);
        QVERIFY(QTest::qWaitFor([&] { return model->driveValue(velocity).has_value(); },
                                kDeviceTimeoutMs));
        QCOMPARE(*model->driveValue(velocity), QStringLiteral("200"));
        Compax3MotionPage* motion = c3->motionPage();
        shell->window()->showPage(motion);
        {
            auto yes = answerConfirmation(true);
            motion->runMotion(comm::Compax3Motion::Enable);
            QVERIFY(QTest::qWaitFor(
                [&] { return motion->axisText().startsWith(QLatin1String("Powered")); },
                kDeviceTimeoutMs));
        }
        motion->findChild<QSpinBox*>(QStringLiteral("compax3Set"))->setValue(3);
        auto* mode = motion->findChild<QLabel*>(QStringLiteral("compax3SetMode"));
        QVERIFY(QTest::qWaitFor([&] { return mode->text().startsWith(QLatin1String("absolute")); },
                                kDeviceTimeoutMs));
        auto* target = motion->findChild<QDoubleSpinBox*>(QStringLiteral("compax3Target"));
        QCOMPARE(target->value(), 300.0);  // set 3 as the drive holds it
        motion->findChild<QDoubleSpinBox*>(QStringLiteral("compax3Velocity"))->setValue(5000);
        QString question;
        NextDialog<QMessageBox> yes([&question](QMessageBox* box) {
            question = box->informativeText() + box->detailedText() + box->text();
            for (QAbstractButton* button : box->buttons())
                if (box->buttonRole(button) != QMessageBox::RejectRole) {
                    button->click();
                    return;
                }
        });
        motion->moveSet();
        QVERIFY(QTest::qWaitFor([&] { return !question.isEmpty(); }, kDeviceTimeoutMs));
        QVERIFY2(question.contains(QStringLiteral("Velocity: 200 → 5000 (written first)")) &&
                     question.contains(QLatin1String("Target: 300 (as read)")) &&
                     question.contains(QLatin1String("Mode (1905.3): absolute")),
                 qPrintable(question));
        // The Objects page shows the written velocity as the drive's.
        QVERIFY2(
            QTest::qWaitFor([&] { return model->driveValue(velocity) == QStringLiteral("5000"); },
                            kDeviceTimeoutMs),
            qPrintable(model->driveValue(velocity).value_or(QString())));
    }

    void objectsTheDriveLacksAreGreyed() {
        // Issue 29 item 2, with a drive that differs from the default one
        // in type and objects.
        std::unique_ptr<Shell> shell = startOnSimulator(
            QStringLiteral("sim:type=S150V4;lacks=1901.0,1902.0"), QStringLiteral("compax3"));
        QVERIFY(shell);
        Compax3Window* c3 = compax3Window(shell->window());
        QCOMPARE(c3->facts().identity.type(), QStringLiteral("S150V4"));
        Compax3ObjectModel* model = c3->objectsPage()->model();
        auto lacking = [model] {
            return model->indexOf(comm::compax3SetTarget(0), Compax3ObjectModel::DriveValue);
        };
        QVERIFY(QTest::qWaitFor(
            [&] { return lacking().data().toString() == QLatin1String("not on this drive"); },
            kDeviceTimeoutMs));
        QVERIFY(lacking().data(Qt::ToolTipRole).toString().contains(QLatin1String("!0002")));
        QVERIFY(model->driveValue(comm::compax3SetTarget(1)).has_value());
    }

    void watchAndParameters() {
        std::unique_ptr<Shell> shell = startCompax3();
        QVERIFY(shell);
        Compax3Window* c3 = compax3Window(shell->window());
        Compax3WatchPage* watch = c3->watchPage();
        shell->window()->showPage(watch);
        QVERIFY(watch->addObject(QStringLiteral("o1901.3")));
        QVERIFY(!watch->addObject(QStringLiteral("1904.1")));  // a function: never read
        QVERIFY(
            QTest::qWaitFor([&] { return watch->chart()->pointCount() >= 4; }, kDeviceTimeoutMs));
        QCOMPARE(watch->table()->rowCount(), 2);  // the position, and what was added
        QCOMPARE(watch->table()->item(1, 2)->text(), QStringLiteral("300"));

        QTemporaryDir dir;
        const QString file = dir.filePath(QStringLiteral("drive.json"));
        Compax3ParametersPage* parameters = c3->parametersPage();
        shell->window()->showPage(parameters);
        parameters->saveToFile(file);
        QVERIFY(QTest::qWaitFor(
            [&] { return resultOf(parameters).startsWith(QLatin1String("Saved 192")); },
            kDeviceTimeoutMs));
        // A change on the drive, then compare: one difference, ticked.
        c3->objectsPage()->model()->setEdit(comm::compax3SetVelocity(4), QStringLiteral("77"));
        {
            auto yes = answerConfirmation(true);
            c3->objectsPage()->writeChanges();
            QVERIFY(QTest::qWaitFor([&] { return c3->objectsPage()->model()->edits().isEmpty(); },
                                    kDeviceTimeoutMs));
        }
        parameters->compareWith(file);
        QVERIFY(QTest::qWaitFor([&] { return parameters->differences()->rowCount() == 1; },
                                kDeviceTimeoutMs));
        QCOMPARE(parameters->differences()->item(0, 0)->text(), QStringLiteral("1902.4"));
        QCOMPARE(parameters->differences()->item(0, 3)->text(), QStringLiteral("77"));
        auto yes = answerConfirmation(true);
        QString report;
        NextDialog<ReportDialog> close([&report](ReportDialog* dialog) {
            report = dialog->windowTitle();
            dialog->accept();
        });
        parameters->writeFile(true);
        QVERIFY(
            QTest::qWaitFor([&] { return resultOf(parameters).startsWith(QLatin1String("Equal")); },
                            kDeviceTimeoutMs));
        QCOMPARE(parameters->differences()->rowCount(), 0);
        QCOMPARE(report, QStringLiteral("Write"));
    }

    // Issue 35, item 8: a parameter file goes only to the drive it was read
    // from. A file of another drive (serial number C3-9999) asks first,
    // showing both identities; declined, nothing is written and no further
    // question comes; accepted, the drive answering takes the file.
    void anotherDrivesFileAsksWhetherThisOneReplacesIt() {
        std::unique_ptr<Shell> shell =
            startOnSimulator(QStringLiteral("sim:serial=C3-2002"), QStringLiteral("compax3"));
        QVERIFY(shell);
        Compax3Window* c3 = compax3Window(shell->window());
        QCOMPARE(c3->facts().identity.serial, QStringLiteral("C3-2002"));
        QTemporaryDir dir;
        const QString file = dir.filePath(QStringLiteral("old-drive.json"));
        Compax3ParametersPage* parameters = c3->parametersPage();
        shell->window()->showPage(parameters);
        parameters->saveToFile(file);
        QVERIFY(
            QTest::qWaitFor([&] { return resultOf(parameters).startsWith(QLatin1String("Saved")); },
                            kDeviceTimeoutMs));
        // The file as if read from the drive this one replaces, with a
        // velocity this drive does not hold.
        Result<Compax3ParameterSet> set = loadCompax3Parameters(file);
        QVERIFY(set.ok());
        Compax3ParameterSet old = *set;
        old.drive.serial = QStringLiteral("C3-9999");
        for (Compax3ParameterValue& value : old.values)
            if (value.id == comm::compax3SetVelocity(4)) value.value = QStringLiteral("77");
        QVERIFY(saveCompax3Parameters(file, old).ok());
        parameters->compareWith(file);
        QVERIFY(QTest::qWaitFor([&] { return parameters->differences()->rowCount() == 1; },
                                kDeviceTimeoutMs));

        // Every dialog in turn: the question (answered as `accept` says),
        // the confirmation (yes), the report (closed).
        QStringList questions;
        int confirmations = 0;
        int reports = 0;
        bool accept = false;
        QTimer answer;
        answer.setInterval(10);
        connect(&answer, &QTimer::timeout, this, [&] {
            QWidget* modal = QApplication::activeModalWidget();
            if (auto* report = qobject_cast<ReportDialog*>(modal)) {
                ++reports;
                report->accept();
                return;
            }
            auto* box = qobject_cast<QMessageBox*>(modal);
            if (!box) return;
            if (box->objectName() != QLatin1String("replacementQuestion")) {
                ++confirmations;
                answerYes(box);
                return;
            }
            questions << box->text() + QLatin1Char('\n') + box->informativeText();
            QAbstractButton* replace =
                box->findChild<QAbstractButton*>(QStringLiteral("acceptReplacement"));
            QVERIFY(replace);
            QCOMPARE(box->defaultButton(), box->button(QMessageBox::Cancel));
            (accept ? replace : box->button(QMessageBox::Cancel))->click();
        });
        answer.start();

        parameters->writeFile(false);
        QVERIFY(QTest::qWaitFor([&] { return questions.size() == 1; }, kDeviceTimeoutMs));
        QVERIFY2(questions.at(0).contains(QLatin1String("not the one")), qPrintable(questions[0]));
        QVERIFY2(questions.at(0).contains(
                     QStringLiteral("serial: backup C3-9999, this device C3-2002  ← differs")),
                 qPrintable(questions.at(0)));
        QVERIFY2(questions.at(0).contains(QLatin1String("type: S025V2 (the same)")),
                 qPrintable(questions.at(0)));
        QTest::qWait(200);
        QCOMPARE(confirmations, 0);  // declined: not even asked whether to write
        // The drive still holds its own velocity.
        parameters->differences()->setRowCount(0);
        parameters->compareWith(file);
        QVERIFY(QTest::qWaitFor([&] { return parameters->differences()->rowCount() == 1; },
                                kDeviceTimeoutMs));
        QVERIFY(parameters->differences()->item(0, 3)->text() != QLatin1String("77"));

        accept = true;
        parameters->writeFile(false);
        QVERIFY(
            QTest::qWaitFor([&] { return resultOf(parameters).startsWith(QLatin1String("Equal")); },
                            kDeviceTimeoutMs));
        QCOMPARE(questions.size(), 2);
        QCOMPARE(confirmations, 1);
        QCOMPARE(reports, 1);
    }

    // Issue 27: the pages on the shell's poll cycle. A parameter backup
    // from the Parameters page holds the line: the Status page's lamps and
    // values say "paused" and name it; the line lost, "no answer since".
    void statusSaysPausedDuringABackupAndNoAnswerSinceWhenTheLineIsLost() {
        std::unique_ptr<Shell> shell = startCompax3();
        QVERIFY(shell);
        Compax3Window* c3 = compax3Window(shell->window());
        Compax3StatusPage* status = c3->statusPage();
        shell->window()->showPage(status);
        QVERIFY(QTest::qWaitFor([&] { return status->freshness()->isLive(); }, kDeviceTimeoutMs));
        const auto* line = status->findChild<QLabel*>(QStringLiteral("pageFreshness"));
        const auto* axis = status->findChild<QLabel*>(QStringLiteral("compax3AxisLine"));
        QVERIFY2(line->text().startsWith(QLatin1String("Live")), qPrintable(line->text()));
        QVERIFY(!lampGrey(status, 10));

        QSignalSpy started(&shell->session()->worker(), &comm::JobRunner::jobStarted);
        QTemporaryDir dir;
        const QString file = dir.filePath(QStringLiteral("drive.json"));
        Compax3ParametersPage* parameters = c3->parametersPage();
        parameters->saveToFile(file);
        const QString backup = QStringLiteral("Save drive parameters");
        QVERIFY(QTest::qWaitFor([&] { return jobStarted(started, backup); }, kDeviceTimeoutMs));
        QCoreApplication::processEvents();
        // Two cycles (driven here, not waited for): a poll queued, then a
        // whole cycle spent behind the backup.
        c3->pollCycle()->tick();
        c3->pollCycle()->tick();
        QCOMPARE(status->freshness()->state(), LiveFreshness::State::Paused);
        QVERIFY2(line->text().startsWith(QLatin1String("Paused (Save drive parameters)")),
                 qPrintable(line->text()));
        const QString paused = QStringLiteral("(paused (Save drive parameters), read ");
        QVERIFY2(axis->text().contains(paused), qPrintable(axis->text()));
        QVERIFY2(status->errorText().contains(paused), qPrintable(status->errorText()));
        for (int bit : {0, 10}) QVERIFY(lampGrey(status, bit));
        // The backup done, the values are live again.
        QVERIFY(QTest::qWaitFor([&] { return QFile::exists(file); }, kDeviceTimeoutMs));
        QVERIFY(QTest::qWaitFor([&] { return status->freshness()->isLive(); }, kDeviceTimeoutMs));
        QVERIFY(!axis->text().contains(QLatin1String("paused")));
        QVERIFY(!lampGrey(status, 10));

        // The line goes: the values stay, grey, "no answer since".
        auto leave = answerLeaveQuestion();
        shell->session()->disconnectFromDevice();
        QVERIFY(QTest::qWaitFor([&] { return status->freshness()->isStale(); }, kDeviceTimeoutMs));
        const QString since = status->freshness()->lastAnswerText();
        QCOMPARE(line->text(), QStringLiteral("No answer since %1").arg(since));
        QVERIFY2(axis->text().endsWith(QStringLiteral("(no answer since %1)").arg(since)),
                 qPrintable(axis->text()));
        QVERIFY(lampGrey(status, 10));
    }

    // A job waiting for the line when STOP is pressed is dropped; the page
    // Issue 35 item 7: the start question names the set's values and when
    // they were read; the start reads the set again before anything is
    // sent, and when the drive holds other values (written on the Objects
    // page meanwhile) it sends nothing and asks again with them.
    void aSetStartChangedOnTheDriveIsAskedAgain() {
        std::unique_ptr<Shell> shell = startCompax3();
        Compax3MotionPage* motion = enabledMotionPage(shell);
        QVERIFY(motion);
        Compax3Window* c3 = compax3Window(shell->window());
        auto* mode = motion->findChild<QLabel*>(QStringLiteral("compax3SetMode"));
        auto* target = motion->findChild<QDoubleSpinBox*>(QStringLiteral("compax3Target"));
        QVERIFY(QTest::qWaitFor([&] { return mode->text().startsWith(QLatin1String("absolute")); },
                                kDeviceTimeoutMs));
        QCOMPARE(target->value(), 100.0);  // set 1 as read

        // Set 1's target written on the Objects page, as a person would.
        Compax3ObjectsPage* objects = c3->objectsPage();
        Compax3ObjectModel* model = objects->model();
        const Compax3ObjectId target1 = comm::compax3SetTarget(1);
        QVERIFY(QTest::qWaitFor([&] { return model->driveValue(target1).has_value(); },
                                kDeviceTimeoutMs));
        QVERIFY(model->setData(model->indexOf(target1, Compax3ObjectModel::NewValue),
                               QStringLiteral("5000")));
        {
            auto yes = answerConfirmation(true);
            objects->writeChanges();
            QVERIFY(QTest::qWaitFor(
                [&] { return model->driveValue(target1) == QStringLiteral("5000"); },
                kDeviceTimeoutMs));
        }
        QCOMPARE(target->value(), 100.0);  // the Motion page still shows what it read

        AnswerEach answers({true, false});
        motion->moveSet();
        QVERIFY(QTest::qWaitFor([&] { return answers.asked.size() == 2; }, kDeviceTimeoutMs));
        const QString first = answers.asked.at(0);
        QVERIFY2(first.contains(QLatin1String("Set 1 as read from the drive at ")) &&
                     first.contains(QLatin1String("Target: 100 (as read)")),
                 qPrintable(first));
        const QString again = answers.asked.at(1);
        QVERIFY2(again.contains(QLatin1String("changed on the drive since")) &&
                     again.contains(QStringLiteral("target 100 → 5000")) &&
                     again.contains(QLatin1String("nothing was sent")) &&
                     again.contains(QLatin1String("Target: 5000 (as read)")),
                 qPrintable(again));
        QCOMPARE(target->value(), 5000.0);
        // Declined: nothing moved.
        QTest::qWait(500);
        QVERIFY2(motion->axisText().startsWith(QLatin1String("Powered, standing at 0")),
                 qPrintable(motion->axisText()));
    }

    void aSetStartShowsAndWritesTheDecelerationApart() {
        // Issue 35 item 7: the acceleration typed is no longer written to
        // the deceleration too; each is shown old and new, written only as
        // the person changed it.
        std::unique_ptr<Shell> shell = startCompax3();
        Compax3MotionPage* motion = enabledMotionPage(shell);
        QVERIFY(motion);
        Compax3Window* c3 = compax3Window(shell->window());
        motion->findChild<QSpinBox*>(QStringLiteral("compax3Set"))->setValue(3);
        auto* mode = motion->findChild<QLabel*>(QStringLiteral("compax3SetMode"));
        auto* deceleration =
            motion->findChild<QDoubleSpinBox*>(QStringLiteral("compax3Deceleration"));
        QVERIFY(QTest::qWaitFor(
            [&] {
                return mode->text().startsWith(QLatin1String("absolute")) &&
                       motion->findChild<QDoubleSpinBox*>(QStringLiteral("compax3Target"))
                               ->value() == 300.0;
            },
            kDeviceTimeoutMs));
        QCOMPARE(deceleration->value(), 1000.0);
        deceleration->setValue(500);
        AnswerEach answers({true});
        motion->moveSet();
        QVERIFY(QTest::qWaitFor([&] { return answers.asked.size() == 1; }, kDeviceTimeoutMs));
        QVERIFY2(answers.asked.first().contains(
                     QStringLiteral("Deceleration: 1000 → 500 (written first)")) &&
                     answers.asked.first().contains(QLatin1String("Acceleration: 1000 (as read)")),
                 qPrintable(answers.asked.first()));
        Compax3ObjectModel* model = c3->objectsPage()->model();
        QVERIFY(QTest::qWaitFor(
            [&] {
                return model->driveValue(comm::compax3SetDeceleration(3)) == QStringLiteral("500");
            },
            kDeviceTimeoutMs));
        QCOMPARE(*model->driveValue(comm::compax3SetAcceleration(3)), QStringLiteral("1000"));
    }

    void disableAsksFirstNamingThatPowerDrops() {
        std::unique_ptr<Shell> shell = startCompax3();
        Compax3MotionPage* motion = enabledMotionPage(shell);
        QVERIFY(motion);
        {
            AnswerEach no({false});
            motion->runMotion(comm::Compax3Motion::Disable);
            QVERIFY(QTest::qWaitFor([&] { return no.asked.size() == 1; }, kDeviceTimeoutMs));
            QVERIFY2(no.asked.first().contains(QLatin1String("Power is dropped")) &&
                         no.asked.first().contains(QLatin1String("axis falls")),
                     qPrintable(no.asked.first()));
        }
        QTest::qWait(300);
        QVERIFY(motion->axisText().startsWith(QLatin1String("Powered")));
        AnswerEach yes({true});
        motion->runMotion(comm::Compax3Motion::Disable);
        QVERIFY(QTest::qWaitFor(
            [&] { return motion->axisText().startsWith(QLatin1String("Powerless")); },
            kDeviceTimeoutMs));
    }

    void leavingADriveReadAsStillCannotTell() {
        // Issue 35 item 7: "powerless" read through the provisional status
        // word is no fact: Disconnect asks, saying it could not tell.
        std::unique_ptr<Shell> shell = startCompax3();
        QVERIFY(shell);
        DeviceSession* session = shell->session();
        QVERIFY(QTest::qWaitFor([session] { return session->motionStop()->armed(); },
                                kDeviceTimeoutMs));
        AnswerEach cancel({false});
        session->disconnectFromDevice();
        QCOMPARE(cancel.asked.size(), 1);
        QVERIFY2(cancel.asked.first().contains(QLatin1String("could not tell")) &&
                     cancel.asked.first().contains(QLatin1String("provisional")),
                 qPrintable(cancel.asked.first()));
        QVERIFY(session->isOnline());
        auto leave = answerLeaveQuestion();
        session->disconnectFromDevice();
        QVERIFY(QTest::qWaitFor([&] { return !session->isOnline(); }, kDeviceTimeoutMs));
    }

    // Issue 35 item 9: a drive answering 150 ms, 400 ms or 1 s late (past
    // the first-byte time): the Motion page's status and set are the
    // drive's, never an answer shifted onto another object.
    void aLateDriveShowsItsOwnValues_data() {
        QTest::addColumn<int>("delayMs");
        QTest::newRow("150 ms") << 150;
        QTest::newRow("400 ms") << 400;
        QTest::newRow("1 s") << 1000;
    }

    void aLateDriveShowsItsOwnValues() {
        QFETCH(int, delayMs);
        std::unique_ptr<Shell> shell = startCompax3();
        QVERIFY(shell);
        Compax3Window* c3 = compax3Window(shell->window());
        Compax3MotionPage* motion = c3->motionPage();
        auto* mode = motion->findChild<QLabel*>(QStringLiteral("compax3SetMode"));
        QVERIFY(QTest::qWaitFor([&] { return mode->text().startsWith(QLatin1String("absolute")); },
                                kDeviceTimeoutMs));
        delayDriveAnswers(shell->session(), delayMs);
        shell->window()->showPage(motion);
        motion->findChild<QSpinBox*>(QStringLiteral("compax3Set"))->setValue(4);
        QStringList seen;
        const int slowMs = kDeviceTimeoutMs + 30 * delayMs;
        QVERIFY2(QTest::qWaitFor(
                     [&] {
                         if (seen.isEmpty() || seen.last() != motion->axisText())
                             seen << motion->axisText();
                         return mode->text().startsWith(QLatin1String("absolute")) &&
                                motion->findChild<QDoubleSpinBox*>(QStringLiteral("compax3Target"))
                                        ->value() == 400.0 &&
                                motion->axisText().startsWith(QLatin1String("Powerless at 0"));
                     },
                     slowMs),
                 qPrintable(seen.join(QLatin1String(" | ")) + QLatin1String(" / ") + mode->text()));
        QCOMPARE(motion->findChild<QDoubleSpinBox*>(QStringLiteral("compax3Velocity"))->value(),
                 200.0);
        QCOMPARE(motion->findChild<QDoubleSpinBox*>(QStringLiteral("compax3Acceleration"))->value(),
                 1000.0);
        for (const QString& text : seen)
            QVERIFY2(!text.startsWith(QLatin1String("Moving")), qPrintable(text));
        QVERIFY2(!resultOf(motion).contains(QLatin1String("not on this drive")),
                 qPrintable(resultOf(motion)));
    }

    // that waits for it hears that it was not sent.
    void aReadDroppedByStopSaysNotSent() {
        std::unique_ptr<Shell> shell = startCompax3();
        QVERIFY(shell);
        Compax3MotionPage* motion = compax3Window(shell->window())->motionPage();
        shell->window()->showPage(motion);
        QVERIFY(
            QTest::qWaitFor([&] { return motion->stopButton()->isEnabled(); }, kDeviceTimeoutMs));
        // A job of the test's own holds the line, so that the read waits
        // (released also when a check fails, so that the worker can stop).
        QSemaphore gate;
        auto release = qScopeGuard([&gate] { gate.release(); });
        QSignalSpy started(&shell->session()->worker(), &comm::JobRunner::jobStarted);
        shell->session()->worker().submit(comm::JobPriority::User, QStringLiteral("hold"),
                                          [&gate](comm::JobContext&) { gate.acquire(); });
        QVERIFY(QTest::qWaitFor([&] { return jobStarted(started, QStringLiteral("hold")); },
                                kDeviceTimeoutMs));
        started.clear();  // the reads of the page's start are done
        QSignalSpy said(motion, &SectionPage::statusMessage);
        motion->readSet();
        motion->stopButton()->click();
        const QString dropped = QStringLiteral("Set 1 not read: not sent: dropped by STOP.");
        QVERIFY(QTest::qWaitFor(
            [&] {
                for (const QList<QVariant>& message : said)
                    if (message.first().toString() == dropped) return true;
                return false;
            },
            kDeviceTimeoutMs));
        QVERIFY(!jobStarted(started, QStringLiteral("Read set 1")));
        release.dismiss();
        gate.release();
        QVERIFY(QTest::qWaitFor([&] { return !shell->session()->motionStop()->stopRunning(); },
                                kDeviceTimeoutMs));
        QVERIFY(!jobStarted(started, QStringLiteral("Read set 1")));  // never sent afterwards
    }
};

QTEST_MAIN(Compax3PagesTest)
#include "tst_compax3_pages.moc"
