// Issue 36 items 6 and 7 in the machine window: always the right devices
// (simulators on pseudo-terminals whose ports now hold another device; a
// drive that is not the one the machine file records; a line that goes
// while no page of its device polls) and the unwritten edits of every
// family, one menu bar, columns that fit in both languages. Real widgets,
// the real QSerialPort, each simulator on its own pty.
#include "machine_fixture.h"
#include "shell_fixture.h"

#include "comm/compax3/compax3_objects.h"
#include "comm/sim/sim_pty_server.h"
#include "comm/sim/simulator_registry.h"
#include "model/machine/machine_file.h"
#include "ui/compax3/compax3_gui.h"
#include "ui/compax3/compax3_object_model.h"
#include "ui/connection_status.h"
#include "ui/device_session.h"
#include "ui/machine/machine.h"
#include "ui/machine/machine_unit.h"
#include "ui/machine/machine_window.h"

#include <QHeaderView>
#include <QMenuBar>
#include <QScreen>
#include <QScrollBar>
#include <QTreeWidget>

using namespace cambench;
using namespace cambench::test;

namespace {

// A family's simulated device served on a pty of its own, as cambench-sim
// serves it: `port` the in-process port's keys ("sim:serial=C3-2").
class PtySimulator {
public:
    PtySimulator(const QString& family, const QString& port, const QString& protocol = {}) {
        const comm::SimulatorInfo* info = comm::SimulatorRegistry::instance().find(family);
        if (!info) return;
        Result<comm::SimulatedLine> line = info->fromPort(port, comm::SerialSettings{}, protocol);
        if (!line) return;
        m_line = std::make_unique<comm::SimulatedLine>(std::move(line).value());
        m_server = std::make_unique<comm::SimPtyServer>(*m_line->endpoint, m_line->pacer);
        m_open = m_server->open().ok();
    }
    bool isOpen() const { return m_open; }
    QString path() const { return m_server ? m_server->slavePath() : QString(); }
    // The simulator is killed: its pty goes.
    void kill() {
        m_server.reset();
        m_line.reset();
    }

private:
    std::unique_ptr<comm::SimulatedLine> m_line;
    std::unique_ptr<comm::SimPtyServer> m_server;
    bool m_open = false;
};

bool waitLamp(const MachineUnit* unit, MachineUnit::Lamp lamp) {
    return QTest::qWaitFor([&] { return unit->lamp() == lamp; }, kDeviceTimeoutMs);
}

// Every device's lamp as it changes: none may ever be green.
class LampLog : public QObject {
public:
    explicit LampLog(const Machine& machine) {
        for (MachineUnit* unit : machine.units())
            connect(unit, &MachineUnit::changed, this, [this, unit] {
                if (unit->lamp() == MachineUnit::Lamp::Connected) m_green << unit->name();
            });
    }
    QStringList green() const { return m_green; }

private:
    QStringList m_green;
};

}  // namespace

class TestMachineDevices : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { useTestSettings(); }

    // The simulators restarted on other ptys: the machine file's ports now
    // reach other devices. Each says "another device answers" (or that
    // nothing of its family answers), red, never "connected".
    void swappedPortsSayAnotherDeviceNeverConnected() {
        PtySimulator mc200(QStringLiteral("mc1"), QStringLiteral("sim:variant=mc200v2"),
                           QStringLiteral("mc1"));
        PtySimulator camcon(QStringLiteral("camcon"), QStringLiteral("sim:throttle=0"),
                            QStringLiteral("standard"));
        PtySimulator drive(QStringLiteral("compax3"), QStringLiteral("sim:serial=C3-0002"));
        QVERIFY(mc200.isOpen() && camcon.isOpen() && drive.isOpen());
        MachineFile file;
        file.machine = QStringLiteral("Swapped press");
        // "cams" on the MC200's pty, "press-plc" on the CamCon's.
        file.devices << machineDevice(QStringLiteral("cams"), QStringLiteral("camcon"),
                                      {{QStringLiteral("port"), mc200.path()},
                                       {QStringLiteral("protocol"), QStringLiteral("standard")}})
                     << machineDevice(QStringLiteral("press-plc"), QStringLiteral("mc1"),
                                      {{QStringLiteral("port"), camcon.path()},
                                       {QStringLiteral("protocol"), QStringLiteral("mc1")},
                                       {QStringLiteral("variant"), QStringLiteral("mc200v2")}})
                     << machineDevice(QStringLiteral("feed"), QStringLiteral("compax3"),
                                      {{QStringLiteral("port"), drive.path()}});
        // The drive the machine file records is another one than answers.
        file.devices[2].identity.set(QStringLiteral("serial"), QStringLiteral("C3-0001"));
        file.devices[2].identity.set(QStringLiteral("type"), QStringLiteral("S025V2"));

        Shell shell;
        Machine* machine = shell.openMachine(file, {});
        const LampLog log(*machine);
        MachineUnit* feed = machine->unit(QStringLiteral("feed"));
        MachineUnit* cams = machine->unit(QStringLiteral("cams"));
        MachineUnit* plc = machine->unit(QStringLiteral("press-plc"));
        QVERIFY(waitLamp(feed, MachineUnit::Lamp::AnotherDevice));
        const QString said =
            machineRow(*machine, QStringLiteral("feed"))->text(MachineWindow::State);
        QVERIFY2(said.startsWith(QLatin1String("another device answers: expected serial "
                                               "C3-0001")) &&
                     said.contains(QLatin1String("found serial C3-0002")),
                 qPrintable(said));
        // The devices of another family on their ports: red, named.
        for (MachineUnit* unit : {cams, plc}) {
            QVERIFY2(QTest::qWaitFor(
                         [unit] {
                             return unit->lamp() == MachineUnit::Lamp::AnotherDevice ||
                                    unit->lamp() == MachineUnit::Lamp::Gone;
                         },
                         kDeviceTimeoutMs),
                     qPrintable(unit->name() + QLatin1String(": ") + unit->stateText()));
            const QString text = machineRow(*machine, unit->name())->text(MachineWindow::State);
            QVERIFY2(text.startsWith(QLatin1String("another device answers")) ||
                         text.startsWith(QLatin1String("no answer")) ||
                         text.startsWith(QLatin1String("did not identify itself")),
                     qPrintable(text));
        }
        for (MachineUnit* unit : {cams, plc, feed})
            qInfo("%s: %s", qPrintable(unit->name()), qPrintable(unit->stateText()));
        // A few watch cycles later still red: it is never taken for its device.
        const int cycles = feed->watchCycles();
        QVERIFY(
            QTest::qWaitFor([&] { return feed->watchCycles() >= cycles + 6; }, kDeviceTimeoutMs));
        QCOMPARE(feed->lamp(), MachineUnit::Lamp::AnotherDevice);
        QVERIFY2(cams->lamp() != MachineUnit::Lamp::Connected, qPrintable(cams->stateText()));
        QVERIFY2(plc->lamp() != MachineUnit::Lamp::Connected, qPrintable(plc->stateText()));
        QVERIFY2(log.green().isEmpty(), qPrintable(log.green().join(QLatin1Char(' '))));
        // The machine file still records the drive that belongs there.
        QCOMPARE(machine->file().devices.at(2).identity.value(QStringLiteral("serial")),
                 QStringLiteral("C3-0001"));
        // The single device's status bar is not green either.
        QVERIFY2(!plc->window()->connectionIndicator()->stateText().startsWith(
                     QLatin1String("Connected")),
                 qPrintable(plc->window()->connectionIndicator()->stateText()));
    }

    // A device whose page nobody looks at: its simulator killed, it is said
    // gone within a watch cycle or two; the first device seen is recorded.
    void aLineThatGoesIsSaidWithinACycleWithoutAPagePolling() {
        PtySimulator camcon(QStringLiteral("camcon"), QStringLiteral("sim:throttle=0"),
                            QStringLiteral("standard"));
        PtySimulator drive(QStringLiteral("compax3"), QStringLiteral("sim:serial=C3-0007"));
        QVERIFY(camcon.isOpen() && drive.isOpen());
        MachineFile file;
        file.machine = QStringLiteral("Press");
        file.devices << machineDevice(QStringLiteral("cams"), QStringLiteral("camcon"),
                                      {{QStringLiteral("port"), camcon.path()},
                                       {QStringLiteral("protocol"), QStringLiteral("standard")}})
                     << machineDevice(QStringLiteral("feed"), QStringLiteral("compax3"),
                                      {{QStringLiteral("port"), drive.path()}});
        Shell shell;
        Machine* machine = shell.openMachine(file, {});
        MachineUnit* feed = machine->unit(QStringLiteral("feed"));
        QVERIFY(waitLamp(feed, MachineUnit::Lamp::Connected));
        QVERIFY(waitLamp(machine->unit(QStringLiteral("cams")), MachineUnit::Lamp::Connected));
        // Recorded once known: the drive that answered.
        QCOMPARE(machine->file().devices.at(1).identity.value(QStringLiteral("serial")),
                 QStringLiteral("C3-0007"));
        machine->window()->showDevice(QStringLiteral("cams"));
        const int before = feed->watchCycles();
        drive.kill();
        QVERIFY(QTest::qWaitFor(
            [&] {
                return machineRow(*machine, QStringLiteral("feed"))
                    ->text(MachineWindow::State)
                    .startsWith(QLatin1String("gone"));
            },
            kDeviceTimeoutMs));
        QCOMPARE(feed->lamp(), MachineUnit::Lamp::Gone);
        QVERIFY2(feed->watchCycles() - before <= 2,
                 qPrintable(QString::number(feed->watchCycles() - before)));
        QCOMPARE(machine->unit(QStringLiteral("cams"))->lamp(), MachineUnit::Lamp::Connected);
    }

    // A Compax3 object typed in and not on the drive counts in the list,
    // the machine's title and the device's, and the quit question asks.
    void aCompax3EditCountsInTheListAndTitle() {
        MachineFile file;
        file.machine = QStringLiteral("Feed line");
        file.devices << machineDevice(QStringLiteral("feed"), QStringLiteral("compax3"),
                                      {{QStringLiteral("port"), QStringLiteral("sim")}});
        Shell shell;
        Machine* machine = shell.openMachine(file, {});
        MachineUnit* feed = machine->unit(QStringLiteral("feed"));
        QVERIFY(waitLamp(feed, MachineUnit::Lamp::Connected));
        QVERIFY(!machine->window()->isWindowModified());
        Compax3Gui* gui = nullptr;
        for (FamilyGui* family : feed->families())
            if (auto* c3 = qobject_cast<Compax3Gui*>(family)) gui = c3;
        QVERIFY(gui);
        QVERIFY(gui->objects()->setEdit(comm::compax3SetVelocity(1), QStringLiteral("321")));
        QCOMPARE(feed->unwrittenCount(), 1);
        QCOMPARE(machineRow(*machine, QStringLiteral("feed"))->text(MachineWindow::Unwritten),
                 QStringLiteral("1"));
        QVERIFY(machine->window()->isWindowModified());
        QVERIFY2(machine->window()->windowTitle().contains(QLatin1String("not written")),
                 qPrintable(machine->window()->windowTitle()));
        QVERIFY(feed->window()->isWindowModified());
        // Quitting asks; Cancel keeps the machine open and the edit.
        const auto cancel = answerConfirmation(false);
        QVERIFY(!machine->window()->confirmClose());
        QCOMPARE(cancel->answered(), 1);
        QCOMPARE(feed->unwrittenCount(), 1);
        // A language switch rebuilds the windows; the typed value stays.
        shell.switchLanguage(QStringLiteral("en"));
        QCOMPARE(feed->unwrittenCount(), 1);
        QCOMPARE(machineRow(*machine, QStringLiteral("feed"))->text(MachineWindow::Unwritten),
                 QStringLiteral("1"));
        gui->objects()->clearEdits();
        QCOMPARE(machineRow(*machine, QStringLiteral("feed"))->text(MachineWindow::Unwritten),
                 QString());
        QVERIFY(!machine->window()->isWindowModified());
    }

    // One menu bar: the Machine menu and the shown device's own menus; the
    // device's window shows none of its own.
    void oneMenuBarWithTheShownDevicesMenus() {
        MachineFile file;
        file.machine = QStringLiteral("Two");
        file.devices << machineDevice(QStringLiteral("cams"), QStringLiteral("camcon"),
                                      {{QStringLiteral("port"), QStringLiteral("sim:throttle=0")},
                                       {QStringLiteral("protocol"), QStringLiteral("standard")}})
                     << machineDevice(QStringLiteral("feed"), QStringLiteral("compax3"),
                                      {{QStringLiteral("port"), QStringLiteral("sim")}});
        Shell shell;
        Machine* machine = shell.openMachine(file, {});
        MachineWindow* window = machine->window();
        for (const QString& name : {QStringLiteral("cams"), QStringLiteral("feed")}) {
            window->showDevice(name);
            MainWindow* own = machine->unit(name)->window();
            QVERIFY(!own->menuBar()->isVisibleTo(window));
            const QList<QAction*> shown = window->menuBar()->actions();
            QCOMPARE(shown.first()->text(), QStringLiteral("&Machine"));
            QCOMPARE(shown.size(), own->menuBar()->actions().size() + 1);
            for (QAction* action : own->menuBar()->actions()) QVERIFY(shown.contains(action));
        }
    }

    // The list's columns show every family's and port's name whole, in
    // English and in German.
    void theListsColumnsFitInBothLanguages() {
        MachineFile file;
        file.machine = QStringLiteral("Three");
        file.devices << machineDevice(QStringLiteral("cams"), QStringLiteral("camcon"),
                                      {{QStringLiteral("port"), QStringLiteral("sim:throttle=0")},
                                       {QStringLiteral("protocol"), QStringLiteral("standard")}})
                     << machineDevice(
                            QStringLiteral("press-plc"), QStringLiteral("mc1"),
                            {{QStringLiteral("port"), QStringLiteral("sim:variant=mc200v2")},
                             {QStringLiteral("protocol"), QStringLiteral("mc1")},
                             {QStringLiteral("variant"), QStringLiteral("mc200v2")}})
                     << machineDevice(QStringLiteral("feed"), QStringLiteral("compax3"),
                                      {{QStringLiteral("port"), QStringLiteral("sim")}});
        Shell shell;
        Machine* machine = shell.openMachine(file, {});
        for (const char* language : {"en", "de"}) {
            shell.switchLanguage(QString::fromLatin1(language));
            QTreeWidget* list = machine->window()->deviceList();
            QVERIFY(QTest::qWaitForWindowExposed(machine->window()));
            QCoreApplication::processEvents();
            for (int i = 0; i < list->topLevelItemCount(); ++i) {
                QTreeWidgetItem* item = list->topLevelItem(i);
                for (int column :
                     {MachineWindow::Name, MachineWindow::Family, MachineWindow::Port}) {
                    const int needed = list->fontMetrics().horizontalAdvance(item->text(column));
                    QVERIFY2(list->header()->sectionSize(column) >= needed,
                             qPrintable(QStringLiteral("%1: \"%2\" in %3 px, needs %4")
                                            .arg(QLatin1String(language), item->text(column))
                                            .arg(list->header()->sectionSize(column))
                                            .arg(needed)));
                }
            }
            // Nothing out of sight to the right where the screen has room for
            // the whole list beside the device's window. A narrower screen
            // (the offscreen one of a test run, 800 pixels) keeps the window
            // within it: the list scrolls sideways instead.
            const int columns = list->header()->length();
            const int room = machine->window()->screen()->availableGeometry().width();
            const int beside = machine->window()->minimumSizeHint().width() - list->minimumWidth();
            if (room >= columns + beside)
                QCOMPARE(list->horizontalScrollBar()->maximum(), 0);
            else
                QVERIFY(list->minimumWidth() < columns);
            // The drive's objects carry their units in the language in use.
            for (FamilyGui* family : machine->unit(QStringLiteral("feed"))->families())
                if (auto* c3 = qobject_cast<Compax3Gui*>(family)) {
                    const QString unit =
                        c3->objects()
                            ->indexOf(comm::compax3SetVelocity(1), Compax3ObjectModel::Unit)
                            .data()
                            .toString();
                    QCOMPARE(unit, QString::fromLatin1(language) == QLatin1String("de")
                                       ? QStringLiteral("Einheit/s")
                                       : QStringLiteral("unit/s"));
                }
        }
        shell.switchLanguage(QStringLiteral("en"));
    }
};

QTEST_MAIN(TestMachineDevices)
#include "tst_machine_devices.moc"
