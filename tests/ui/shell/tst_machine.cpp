// Issue 30 items 2 and 4: the machine in the GUI. Real widgets, each device
// on its own in-process simulated device through its own worker: two
// devices of different families at once, each with its own identity; one
// going away leaves the other as it was; the STOP of any device's page
// stops the device that moves and the status bar names it; a machine file
// saved and opened again lists the same devices.
#include "machine_fixture.h"
#include "shell_fixture.h"
#include "stop_reach_checks.h"

#include "../mc1/mc1_jog.h"

#include "model/machine/machine_file.h"
#include "ui/camcon/backup_wizard.h"
#include "ui/camcon/compare_programs_dialog.h"
#include "ui/connection_status.h"
#include "ui/device_session.h"
#include "ui/family_gui.h"
#include "ui/machine/demo_machine.h"
#include "ui/machine/machine.h"
#include "ui/machine/machine_connection.h"
#include "ui/machine/machine_progress.h"
#include "ui/machine/machine_report.h"
#include "ui/machine/machine_stop.h"
#include "ui/machine/machine_unit.h"
#include "ui/machine/machine_window.h"
#include "ui/mc1/mc1_axes_page.h"
#include "ui/mc1/mc1_window.h"
#include "ui/motion_stop.h"
#include "ui/stop_bar.h"

#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QScreen>
#include <QStatusBar>
#include <QTextDocument>
#include <QTreeWidget>

using namespace cambench;
using namespace cambench::test;

namespace {

// The CamCon and the MC200 open in a machine's window, both identified.
struct CamsAndPlc {
    Shell shell;
    Machine* machine = nullptr;
    MachineUnit* cams = nullptr;
    MachineUnit* plc = nullptr;
};
std::unique_ptr<CamsAndPlc> openCamsAndPlc() {
    auto open = std::make_unique<CamsAndPlc>();
    open->machine = open->shell.openMachine(camsAndPlc(), {});
    if (!waitIdentified(*open->machine)) return nullptr;
    open->cams = open->machine->unit(QStringLiteral("cams"));
    open->plc = open->machine->unit(QStringLiteral("press-plc"));
    return open;
}

// The MC200's axis 1 jogs (confirmed on its Axes page); then its window
// shows its Connection page (no poll: the line is quiet but for the test)
// unless `keepPolling`, and the machine shows the CamCon's pages.
bool jogThePlc(const CamsAndPlc& open, bool keepPolling = false) {
    MainWindow* plc = open.plc->window();
    open.machine->window()->showDevice(QStringLiteral("press-plc"));
    Mc1AxesPage* axes = mc1Window(plc)->axesPage();
    if (!jogPlus(plc, axes)) return false;
    if (keepPolling) return true;
    open.machine->window()->showDevice(QStringLiteral("cams"));
    return leaveForQuietPage(plc, axes);
}

}  // namespace

class TestMachine : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { useTestSettings(); }

    void twoDevicesOfTwoFamiliesAtOnceAndOneGoesAway() {
        const std::unique_ptr<CamsAndPlc> open = openCamsAndPlc();
        QVERIFY(open);
        Machine* machine = open->machine;
        MachineUnit* cams = open->cams;
        MachineUnit* plc = open->plc;
        // Each its own connection and worker.
        QVERIFY(cams->session() != plc->session());
        QVERIFY(&cams->session()->worker() != &plc->session()->worker());
        // Each window names its own device.
        const QString camsIdentity = cams->window()->connectionStrip()->text();
        const QString plcIdentity = plc->window()->connectionStrip()->text();
        QVERIFY2(camsIdentity.contains(QLatin1String("CamCon")), qPrintable(camsIdentity));
        QVERIFY2(plcIdentity.contains(QLatin1String("MC200")), qPrintable(plcIdentity));
        QVERIFY(!camsIdentity.contains(QLatin1String("MC200")));
        // The list: name, family, port, lamp in words.
        QCOMPARE(machine->window()->deviceList()->topLevelItemCount(), 2);
        QCOMPARE(machineRow(*machine, QStringLiteral("press-plc"))->text(MachineWindow::Port),
                 QStringLiteral("sim:variant=mc200v2"));
        QCOMPARE(machineRow(*machine, QStringLiteral("cams"))->text(MachineWindow::State),
                 QStringLiteral("connected"));
        // Switching shows the other device's pages.
        machine->window()->showDevice(QStringLiteral("press-plc"));
        QCOMPARE(machine->window()->currentDevice(), QStringLiteral("press-plc"));
        QVERIFY(plc->window()->isVisibleTo(machine->window()));
        QVERIFY(!cams->window()->isVisibleTo(machine->window()));

        // The MC200 goes away: its row says so, the CamCon stays as it was.
        QSignalSpy camsLine(cams->session(), &DeviceSession::stateChanged);
        {
            // "Not moving" read through the guessed parameter numbers is no
            // fact: the disconnect asks (issue 35).
            auto leave = answerLeaveQuestion(QStringLiteral("leaveWithoutStop"));
            QVERIFY(plc->session()->disconnectFromDevice());
            QCOMPARE(leave->answered(), 1);
        }
        QVERIFY(QTest::qWaitFor([&] { return plc->lamp() == MachineUnit::Lamp::Offline; },
                                kDeviceTimeoutMs));
        QCOMPARE(machineRow(*machine, QStringLiteral("press-plc"))->text(MachineWindow::State),
                 QStringLiteral("offline"));
        QTest::qWait(200);
        QCOMPARE(cams->lamp(), MachineUnit::Lamp::Connected);
        QVERIFY(cams->session()->deviceChecked());
        QCOMPARE(cams->window()->connectionStrip()->text(), camsIdentity);
        QCOMPARE(machineRow(*machine, QStringLiteral("cams"))->text(MachineWindow::State),
                 QStringLiteral("connected"));
        QCOMPARE(camsLine.size(), 0);  // the CamCon's line was not touched
    }

    void stopOnAnyPageStopsTheAxisThatMoves() {
        const std::unique_ptr<CamsAndPlc> open = openCamsAndPlc();
        QVERIFY(open);
        Machine* machine = open->machine;
        MachineUnit* cams = open->cams;
        MachineUnit* plc = open->plc;
        // The CamCon moves nothing, yet its page shows the machine's STOP.
        QVERIFY(QTest::qWaitFor([&] { return machine->stop()->armed(); }, kDeviceTimeoutMs));
        QVERIFY(!cams->session()->motionStop()->available());
        QVERIFY(cams->window()->stopBar()->isVisibleTo(cams->window()));

        // A jog through the MC-1 page's own confirmation.
        machine->window()->showDevice(QStringLiteral("press-plc"));
        Mc1AxesPage* axes = mc1Window(plc->window())->axesPage();
        plc->window()->showPage(axes);
        QVERIFY(QTest::qWaitFor([&] { return axes->freshness()->isLive(); }, kDeviceTimeoutMs));
        const auto yes = answerConfirmation(true);
        axes->findChild<QPushButton*>(QStringLiteral("mc1JogPlus"))->click();
        QCOMPARE(yes->answered(), 1);
        const auto says = [axes](const char* what) {
            return axes->stateLabel()->text().contains(QLatin1String(what));
        };
        QVERIFY(QTest::qWaitFor([&] { return says("jogging +"); }, kDeviceTimeoutMs));

        // STOP on the CamCon's page.
        machine->window()->showDevice(QStringLiteral("cams"));
        QSignalSpy plcStopped(plc->session()->motionStop(), &StopControl::stopFinished);
        QSignalSpy machineStopped(machine->stop(), &StopControl::stopFinished);
        cams->window()->stopBar()->button()->click();
        QVERIFY(machineStopped.wait(kDeviceTimeoutMs));
        QCOMPARE(plcStopped.size(), 1);  // the MC200's own STOP, once
        const auto report = machineStopped.first().first().value<comm::MotionStopReport>();
        QVERIFY(report.allAcknowledged());
        QVERIFY(!report.lines.isEmpty());
        for (const comm::MotionStopLine& line : report.lines)
            QVERIFY2(line.what.startsWith(QLatin1String("press-plc: ")), qPrintable(line.what));
        const QString message = machine->window()->statusBar()->currentMessage();
        QVERIFY2(message.contains(QLatin1String("STOP: acknowledged by press-plc.")),
                 qPrintable(message));
        QVERIFY2(!message.contains(QLatin1String("cams")), qPrintable(message));
        QVERIFY(QTest::qWaitFor([&] { return says("stands at"); }, kDeviceTimeoutMs));

        // A device that can move but is not on the line is named as not reached.
        {
            // "Not moving" read through the guessed parameter numbers is no
            // fact: the disconnect asks (issue 35).
            auto leave = answerLeaveQuestion(QStringLiteral("leaveWithoutStop"));
            QVERIFY(plc->session()->disconnectFromDevice());
            QCOMPARE(leave->answered(), 1);
        }
        QVERIFY(QTest::qWaitFor([&] { return !plc->session()->isOnline(); }, kDeviceTimeoutMs));
        // (Offline by the person's own disconnect: nothing left that can move.)
        QVERIFY(!machine->stop()->armed());
    }

    void theStopKeyStopsFromEveryDevice() {
        Shell shell;
        Machine* machine = shell.openMachine(camsAndPlc(), {});
        QVERIFY(waitIdentified(*machine));
        QVERIFY(QTest::qWaitFor([&] { return machine->stop()->armed(); }, kDeviceTimeoutMs));
        machine->window()->showDevice(QStringLiteral("cams"));
        machine->window()->activateWindow();
        QSignalSpy stopped(machine->stop(), &StopControl::stopFinished);
        QTest::keyClick(machine->window()->deviceList(), Qt::Key_Escape);
        QVERIFY(stopped.wait(kDeviceTimeoutMs));
        QCOMPARE(stopped.size(), 1);  // once, not once per device window
    }

    // Issue 35 item 4: in a machine, no device's dialog blocks another
    // device's STOP. With the MC200 jogging, Escape in the CamCon's dialogs
    // (its own and Qt's) and in the machine's menus and dialogs stops the
    // MC200 - the machine's STOP, once, its telegrams and nothing else -
    // and cancels the dialog.
    void escapeInAnotherDevicesDialogStopsTheMachine() {
        const std::unique_ptr<CamsAndPlc> open = openCamsAndPlc();
        QVERIFY(open);
        Machine* machine = open->machine;
        MainWindow* cams = open->cams->window();
        DeviceSession* plc = open->plc->session();
        QVERIFY(QTest::qWaitFor([&] { return machine->stop()->armed(); }, kDeviceTimeoutMs));
        QVERIFY(jogThePlc(*open));
        const QList<QByteArray> reference = referenceStop(plc, cams->stopBar(), machine->stop());
        QVERIFY(!reference.isEmpty());

        QList<StopPlace> places;
        places << StopPlace{
            QStringLiteral("CamCon's Compare programs"),
            menuEntry(cams, QStringLiteral("&Tools"), QStringLiteral("Compare &programs…")),
            &openDialog<CompareProgramsDialog>};
        places << StopPlace{
            QStringLiteral("CamCon's backup wizard"),
            menuEntry(cams, QStringLiteral("&Device"), QStringLiteral("&Backup and restore…")),
            &openDialog<BackupWizard>};
        places << StopPlace{
            QStringLiteral("CamCon's Open project (file dialog)"),
            menuEntry(cams, QStringLiteral("&File"), QStringLiteral("&Open project…"))};
        places << StopPlace{
            QStringLiteral("CamCon's check report"),
            menuEntry(cams, QStringLiteral("&Help"), QStringLiteral("&Check this device…"))};
        places << openMenu(cams, QStringLiteral("&Edit"));
        places << openMenu(machine->window(), QStringLiteral("&Machine"));
        places << StopPlace{QStringLiteral("machine's Add device (input dialog)"),
                            menuEntry(machine->window(), QStringLiteral("&Machine"),
                                      QStringLiteral("&Add device…"))};
        escapeStopsFromEach(places, plc, machine->stop(), plc->motionStop(), reference,
                            [&open] { return jogThePlc(*open); });
        QCOMPARE(machine->units().size(), 2);  // Add device was cancelled
    }

    // Item 10: the list shows the device that moves as moving (its own
    // live status), then what the STOP did; the window stays on the screen.
    void theListShowsTheDeviceThatMoves() {
        const std::unique_ptr<CamsAndPlc> open = openCamsAndPlc();
        QVERIFY(open);
        Machine* machine = open->machine;
        QVERIFY(QTest::qWaitFor([&] { return machine->stop()->armed(); }, kDeviceTimeoutMs));
        QTreeWidgetItem* plcRow = machineRow(*machine, QStringLiteral("press-plc"));
        QCOMPARE(plcRow->text(MachineWindow::State), QStringLiteral("connected"));
        QVERIFY(jogThePlc(*open, true));
        const auto rowSays = [plcRow](const char* start) {
            return QTest::qWaitFor(
                [&] { return plcRow->text(MachineWindow::State).startsWith(QLatin1String(start)); },
                kDeviceTimeoutMs);
        };
        QVERIFY2(rowSays("connected, moving (axis 1 is jogging +"),
                 qPrintable(plcRow->text(MachineWindow::State)));
        QCOMPARE(open->plc->lamp(), MachineUnit::Lamp::Moving);
        QCOMPARE(machineRow(*machine, QStringLiteral("cams"))->text(MachineWindow::State),
                 QStringLiteral("connected"));
        // The report reads a device that moves all the same (queries only).
        QTemporaryDir dir;
        MachineProgress* report =
            machine->window()->writeReportTo(dir.filePath(QStringLiteral("moving.pdf")));
        QSignalSpy read(report, &MachineProgress::finished);
        QVERIFY(read.wait(kDeviceTimeoutMs));
        QCOMPARE(report->resultLine(QStringLiteral("press-plc")), QStringLiteral("read"));

        // Another page shown: the status is no longer read, only "may move".
        open->plc->window()->showSection(MainWindow::Connection);
        QVERIFY2(rowSays("connected, may move"), qPrintable(plcRow->text(MachineWindow::State)));
        QCOMPARE(open->plc->lamp(), MachineUnit::Lamp::Connected);

        QSignalSpy stopped(machine->stop(), &StopControl::stopFinished);
        machine->window()->showDevice(QStringLiteral("cams"));
        open->cams->window()->stopBar()->button()->click();
        QVERIFY(stopped.wait(kDeviceTimeoutMs));
        // The time as every clock on screen says it, in every language
        // (QLocale's long format said "7:29:03 AM UTC" in English).
        QVERIFY2(QRegularExpression(QStringLiteral("^connected, STOP acknowledged at "
                                                   "\\d\\d:\\d\\d:\\d\\d$"))
                     .match(plcRow->text(MachineWindow::State))
                     .hasMatch(),
                 qPrintable(plcRow->text(MachineWindow::State)));
        // The report (a line per axis) does not make the window grow.
        QTest::qWait(50);
        const QRect screen = machine->window()->screen()->availableGeometry();
        QVERIFY2(
            machine->window()->height() <= screen.height(),
            qPrintable(
                QStringLiteral("%1 > %2").arg(machine->window()->height()).arg(screen.height())));
        QCOMPARE(open->cams->window()->stopBar()->height(),
                 open->cams->window()->stopBar()->minimumHeight());
    }

    // A language switch rebuilds the machine's window and each device's;
    // the lines, the identities and the STOP stay.
    void aLanguageSwitchKeepsEveryLine() {
        const std::unique_ptr<CamsAndPlc> open = openCamsAndPlc();
        QVERIFY(open);
        QSignalSpy camsLine(open->cams->session(), &DeviceSession::stateChanged);
        QSignalSpy plcLine(open->plc->session(), &DeviceSession::stateChanged);
        const MachineWindow* before = open->machine->window();
        open->machine->window()->showDevice(QStringLiteral("press-plc"));
        open->shell.switchLanguage(QStringLiteral("en"));
        QVERIFY(open->machine->window() != before);
        QCOMPARE(open->machine->window()->currentDevice(), QStringLiteral("press-plc"));
        QCOMPARE(open->machine->window()->deviceList()->topLevelItemCount(), 2);
        QCOMPARE(camsLine.size(), 0);
        QCOMPARE(plcLine.size(), 0);
        // A window built on a line asks its device who it is again.
        QVERIFY(QTest::qWaitFor(
            [&] {
                return open->plc->window()->connectionStrip()->text().contains(
                    QLatin1String("MC200"));
            },
            kDeviceTimeoutMs));
        QVERIFY(open->cams->window()->stopBar()->isVisibleTo(open->cams->window()));
        QSignalSpy stopped(open->machine->stop(), &StopControl::stopFinished);
        open->cams->window()->stopBar()->button()->click();
        QVERIFY(stopped.wait(kDeviceTimeoutMs));
    }

    void savedAndOpenedAgainListsTheSameDevices() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("press.json"));
        Shell shell;
        Machine* machine = shell.openMachine(camsAndPlc(), {});
        QVERIFY(waitIdentified(*machine));
        QVERIFY(machine->save(path));
        const QByteArray first = machineFileJson(machine->file());
        QCOMPARE(machineFileJson(machine->file()), first);  // stable
        const Result<MachineFile> read = readMachineFile(path);
        QVERIFY2(read, read ? "" : qPrintable(read.error().message));
        QCOMPARE(read->machine, QStringLiteral("Test press"));
        QCOMPARE(read->devices.size(), 2);
        Machine* again = shell.openMachine(*read, path);
        QVERIFY(waitIdentified(*again));
        QTreeWidget* list = again->window()->deviceList();
        QCOMPARE(list->topLevelItemCount(), 2);
        for (int i = 0; i < 2; ++i) {
            QTreeWidgetItem* before = machine->window()->deviceList()->topLevelItem(i);
            QTreeWidgetItem* after = list->topLevelItem(i);
            for (int column : {MachineWindow::Name, MachineWindow::Family, MachineWindow::Port})
                QCOMPARE(after->text(column), before->text(column));
        }
        QCOMPARE(
            again->unit(QStringLiteral("press-plc"))->device().option(QStringLiteral("variant")),
            QStringLiteral("mc200v2"));
    }

    // Add device: its Connection page says how; the machine file takes
    // what it connected with.
    void anAddedDeviceIsConnectedOnItsPageAndSaved() {
        const std::unique_ptr<CamsAndPlc> open = openCamsAndPlc();
        QVERIFY(open);
        MachineDevice feed;
        feed.name = QStringLiteral("feed");
        const Result<MachineUnit*> added = open->machine->addDevice(feed);
        QVERIFY(added);
        MachineUnit* unit = *added;
        QCOMPARE(open->machine->window()->currentDevice(), QStringLiteral("feed"));
        QCOMPARE(unit->lamp(), MachineUnit::Lamp::Offline);
        QVERIFY(!unit->session()->wantsConnection());
        QVERIFY(machineRow(*open->machine, QStringLiteral("feed"))
                    ->text(MachineWindow::State)
                    .startsWith(QLatin1String("not connected yet")));
        QVERIFY(!open->machine->addDevice(feed));  // the name is taken
        ConnectionPage* page = unit->window()->connectionPage();
        page->setFamily(QStringLiteral("compax3"));
        page->setPort(QStringLiteral("sim"));
        unit->window()->connectAndLoad();
        QVERIFY(
            QTest::qWaitFor([&] { return unit->session()->deviceChecked(); }, kDeviceTimeoutMs));
        const MachineFile file = open->machine->file();
        QCOMPARE(file.devices.size(), 3);
        QCOMPARE(file.devices.at(2).family, QStringLiteral("compax3"));
        QCOMPARE(file.devices.at(2).option(QStringLiteral("port")), QStringLiteral("sim"));
        QCOMPARE(machineRow(*open->machine, QStringLiteral("feed"))->text(MachineWindow::Port),
                 QStringLiteral("sim"));
        QCOMPARE(open->cams->lamp(), MachineUnit::Lamp::Connected);
    }

    void aWrongDeviceIsRefusedNamingItAndTheOthersConnect() {
        MachineFile file = camsAndPlc();
        file.devices[1].options[1].second = QStringLiteral("standard");  // a CamCon protocol
        const Result<MachineConnection> refused = machineConnection(file.devices[1]);
        QVERIFY(!refused);
        QVERIFY2(refused.error().message.startsWith(QLatin1String("press-plc: ")),
                 qPrintable(refused.error().message));
        Shell shell;
        Machine* machine = shell.openMachine(file, {});
        MachineUnit* cams = machine->unit(QStringLiteral("cams"));
        MachineUnit* plc = machine->unit(QStringLiteral("press-plc"));
        QVERIFY(
            QTest::qWaitFor([&] { return cams->session()->deviceChecked(); }, kDeviceTimeoutMs));
        QCOMPARE(plc->lamp(), MachineUnit::Lamp::Gone);
        QVERIFY(!plc->session()->wantsConnection());  // no line opened for it
        QVERIFY(machineRow(*machine, QStringLiteral("press-plc"))
                    ->text(MachineWindow::State)
                    .contains(QLatin1String("not opened: press-plc: the protocol")));
    }

    // Issue 36 item 5: every device's section of its family, read from the
    // device before printing (a bar per device), one date format.
    void theReportHasTheMachineAndEachDevice() {
        Shell shell;
        Machine* machine = shell.openMachine(threeFamilies(), {});
        QVERIFY(waitIdentified(*machine));
        QTemporaryDir dir;
        const QString pdf = dir.filePath(QStringLiteral("press.pdf"));
        MachineProgress* progress = machine->window()->writeReportTo(pdf);
        QCOMPARE(progress->names(),
                 (QList<QString>{QStringLiteral("cams"), QStringLiteral("press-plc"),
                                 QStringLiteral("feed")}));
        QVERIFY(progress->bar(QStringLiteral("feed")));
        QSignalSpy finished(progress, &MachineProgress::finished);
        QVERIFY(finished.wait(kDeviceTimeoutMs));
        for (const QString& name : progress->names())
            QCOMPARE(progress->resultLine(name), QStringLiteral("read"));
        QVERIFY(QTest::qWaitFor([&] { return QFile::exists(pdf); }, kDeviceTimeoutMs));
        QFile written(pdf);
        QVERIFY(written.open(QIODevice::ReadOnly));
        QVERIFY(written.read(5) == "%PDF-");

        QTextDocument document;
        MachineReport::build(document, *machine);
        const QString text = document.toPlainText();
        QVERIFY(text.contains(QLatin1String("Machine report: Test press")));
        for (const MachineUnit* unit : machine->units())
            QVERIFY2(text.contains(unit->name() + QLatin1String(" (")), qPrintable(unit->name()));
        // The CamCon's own report, every program read first.
        QVERIFY(text.contains(QLatin1String("Commissioning report")));
        QVERIFY2(!text.contains(QLatin1String("Not read from the device: its content is "
                                              "unknown.")),
                 qPrintable(text));
        // The MC200's: controller, program, axes through the table in use,
        // variables and flags.
        for (const char* part : {"MC200", "PLC program", "Axes", "Parameter table in use",
                                 "Variables", "External flags", "variables read (V1 to V"})
            QVERIFY2(text.contains(QLatin1String(part)), part);
        // The Compax3's: identity, status and last error, the set with names.
        for (const char* part : {"Serial number C3-4711-0815", "Last error (550.1)",
                                 "Parameter set", "Set 1 velocity", "Read from the drive at"})
            QVERIFY2(text.contains(QLatin1String(part)), part);
        QVERIFY(!text.contains(QLatin1String("last answered: never")));
        QVERIFY(text.contains(QLatin1String("Edits on this PC not written to the device: 0")));
        // One date format on the page: 2025-11-29 14:03, nothing else.
        static const QRegularExpression other(QStringLiteral(
            "\\d{1,2}/\\d{1,2}/\\d{2}|\\d{1,2}\\.\\d{1,2}\\.\\d{2}(?!\\d)|[AP]M\\b"));
        const QRegularExpressionMatch found = other.match(text);
        QVERIFY2(!found.hasMatch(), qPrintable(found.captured()));
        static const QRegularExpression iso(QStringLiteral("\\d{4}-\\d{2}-\\d{2} \\d{2}:\\d{2}"));
        QVERIFY(iso.match(text).hasMatch());
    }

    void theDemoMachineIsBuiltIn() {
        const Result<MachineFile> demo = demoMachineFile();
        QVERIFY2(demo, demo ? "" : qPrintable(demo.error().message));
        QCOMPARE(demo->devices.size(), 3);
        for (const MachineDevice& device : demo->devices) {
            const Result<MachineConnection> connection = machineConnection(device);
            QVERIFY2(connection, connection ? "" : qPrintable(connection.error().message));
            QVERIFY(connection->connection.port.startsWith(QLatin1String("sim")));
        }
        // Opened, it fits a laptop's 1366 pixels: the list beside a device's
        // window (the list's columns once made the window 1598 wide at the
        // least, German 1769, its right edge beyond the screen).
        Shell shell;
        Machine* machine = shell.openMachine(*demo, {});
        QVERIFY(waitIdentified(*machine));
        QVERIFY2(machine->window()->minimumSizeHint().width() <= 1366,
                 qPrintable(QString::number(machine->window()->minimumSizeHint().width())));
    }
};

QTEST_MAIN(TestMachine)
#include "tst_machine.moc"
