// Issue 38 item 4: the machine window tested through the fake family alone
// (tests/family/), so that what it does for any family is not tested only
// through the CamCon's and the MC-1's pages. Two fake devices that differ
// (serial number, number of registers, what the registers hold, number of
// axes), each on its own in-process simulated device and its own worker:
// each its own line; one going away leaves the other as it was; the STOP on
// either's page stops both and says who acknowledged; the machine file
// saved and opened again; backup, verify and restore device by device, a
// value changed behind CamBench's back named on its device's line only,
// and a device swapped for another not restored; two versions in the
// machine's history compared device by device and one marked released.
#include "fake_shell_fixture.h"
#include "history_fixture.h"
#include "machine_fixture.h"

#include "model/file_read.h"
#include "model/machine/machine_backup_folder.h"
#include "model/machine/machine_file.h"
#include "ui/connection_status.h"
#include "ui/device_session.h"
#include "ui/machine/demo_machine.h"
#include "ui/machine/machine.h"
#include "ui/machine/machine_backup_run.h"
#include "ui/machine/machine_history_dialog.h"
#include "ui/machine/machine_progress.h"
#include "ui/machine/machine_stop.h"
#include "ui/machine/machine_unit.h"
#include "ui/machine/machine_window.h"
#include "ui/motion_stop.h"
#include "ui/stop_bar.h"

#include <QDir>
#include <QFile>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTimer>

using namespace cambench;
using namespace cambench::test;

namespace {

const QString kLeft = QStringLiteral("left");
const QString kRight = QStringLiteral("right");

MachineDevice fakeDevice(const QString& name, const QString& port) {
    return machineDevice(name, QStringLiteral("fake"),
                         {{QStringLiteral("port"), port},
                          {QStringLiteral("protocol"), QStringLiteral("fake-line")}});
}

// Two fake devices that differ in everything a device can.
MachineFile twoFakes() {
    MachineFile file;
    file.machine = QStringLiteral("Test line");
    file.devices << fakeDevice(kLeft, QStringLiteral("sim:throttle=0,serial=1,regs=3,axes=2"))
                 << fakeDevice(kRight, QStringLiteral("sim:throttle=0,serial=2,regs=5"));
    return file;
}

std::unique_ptr<OpenedMachine> openTwoFakes() {
    auto open = openWithBackupFolder(twoFakes(), QStringLiteral("line-backup"));
    if (!waitIdentified(*open->machine)) return nullptr;
    return open;
}

// Runs `call` on `name`'s fake device in its worker and waits for its answer.
template <class T>
Result<T> onDevice(Machine& machine, const QString& name,
                   std::function<Result<T>(fake::FakeDevice&)> call) {
    const std::optional<Result<T>> answer = runOn<fake::FakeDevice, T>(
        machine.unit(name),
        [call](fake::FakeDevice& device, comm::JobContext&) { return call(device); });
    if (!answer) return Error::communication(QStringLiteral("no answer in time"));
    return *answer;
}

}  // namespace

class TestMachineShell : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { QVERIFY(setUpWithTheFakeFamily()); }

    void eachDeviceItsOwnLineAndOneGoingAwayLeavesTheOther() {
        const std::unique_ptr<OpenedMachine> open = openTwoFakes();
        QVERIFY(open);
        Machine* machine = open->machine;
        MachineUnit* left = machine->unit(kLeft);
        MachineUnit* right = machine->unit(kRight);
        QVERIFY(left->session() != right->session());
        QVERIFY(&left->session()->worker() != &right->session()->worker());
        // Each window names its own device.
        const QString leftIdentity = left->window()->connectionStrip()->text();
        QVERIFY2(leftIdentity.contains(QLatin1String("serial=1")), qPrintable(leftIdentity));
        QVERIFY2(right->window()->connectionStrip()->text().contains(QLatin1String("serial=2")),
                 qPrintable(right->window()->connectionStrip()->text()));
        QCOMPARE(machine->window()->deviceList()->topLevelItemCount(), 2);
        QCOMPARE(machineRow(*machine, kRight)->text(MachineWindow::Family),
                 QStringLiteral("Fake test device"));
        QCOMPARE(machineRow(*machine, kLeft)->text(MachineWindow::State),
                 QStringLiteral("connected"));
        machine->window()->showDevice(kRight);
        QVERIFY(right->window()->isVisibleTo(machine->window()));
        QVERIFY(!left->window()->isVisibleTo(machine->window()));

        // The right one goes away: its row says so, the left one's line is untouched.
        QSignalSpy leftLine(left->session(), &DeviceSession::stateChanged);
        QVERIFY(right->session()->disconnectFromDevice());
        QVERIFY(QTest::qWaitFor([&] { return right->lamp() == MachineUnit::Lamp::Offline; },
                                kDeviceTimeoutMs));
        QCOMPARE(machineRow(*machine, kRight)->text(MachineWindow::State),
                 QStringLiteral("offline"));
        QTest::qWait(200);
        QCOMPARE(left->lamp(), MachineUnit::Lamp::Connected);
        QCOMPARE(left->window()->connectionStrip()->text(), leftIdentity);
        QCOMPARE(leftLine.size(), 0);
    }

    void theStopOnEitherPageStopsEveryDevice() {
        const std::unique_ptr<OpenedMachine> open = openTwoFakes();
        QVERIFY(open);
        Machine* machine = open->machine;
        QVERIFY(QTest::qWaitFor([&] { return machine->stop()->armed(); }, kDeviceTimeoutMs));
        // The left device's axis 2 moves.
        const Result<QString> moving = onDevice<QString>(
            *machine, kLeft, [](fake::FakeDevice& device) { return device.move(2); });
        QVERIFY2(moving, moving ? "" : qPrintable(moving.error().message));
        fake::clearRequestLog();

        // STOP on the right device's page.
        machine->window()->showDevice(kRight);
        QSignalSpy stopped(machine->stop(), &StopControl::stopFinished);
        machine->unit(kRight)->window()->stopBar()->button()->click();
        QVERIFY(stopped.wait(kDeviceTimeoutMs));
        QCOMPARE(stopped.size(), 1);
        const auto report = stopped.first().first().value<comm::MotionStopReport>();
        QVERIFY(report.allAcknowledged());
        // Every axis of each device, named by its device: left 2, right 1.
        QStringList what;
        for (const comm::MotionStopLine& line : report.lines) what << line.what;
        what.sort();
        QCOMPARE(what, (QStringList{QStringLiteral("left: Axis 1"), QStringLiteral("left: Axis 2"),
                                    QStringLiteral("right: Axis 1")}));
        // Only STOPs went out: nothing moves again by itself.
        for (const QString& request : fake::requestLog())
            QVERIFY2(!request.startsWith(QLatin1String("MOVE")), qPrintable(request));
        const Result<QStringList> after = onDevice<QStringList>(
            *machine, kLeft, [](fake::FakeDevice& device) { return device.activeMotion(); });
        QVERIFY(after);
        QVERIFY2(after->isEmpty(), qPrintable(after->join(QLatin1String(", "))));
    }

    void savedAndOpenedAgainListsTheSameDevices() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("line.json"));
        const std::unique_ptr<OpenedMachine> open = openTwoFakes();
        QVERIFY(open);
        QVERIFY(open->machine->save(path));
        const Result<MachineFile> read = readMachineFile(path);
        QVERIFY2(read, read ? "" : qPrintable(read.error().message));
        QCOMPARE(read->devices.size(), 2);
        Machine* again = open->shell.openMachine(*read, path);
        QVERIFY(waitIdentified(*again));
        for (const QString& name : {kLeft, kRight})
            for (int column : {MachineWindow::Name, MachineWindow::Family, MachineWindow::Port})
                QCOMPARE(machineRow(*again, name)->text(column),
                         machineRow(*open->machine, name)->text(column));
        QVERIFY2(again->unit(kRight)->window()->connectionStrip()->text().contains(
                     QLatin1String("serial=2")),
                 qPrintable(again->unit(kRight)->window()->connectionStrip()->text()));
    }

    void backsUpVerifiesAndRestoresEachDevice() {
        const std::unique_ptr<OpenedMachine> open = openTwoFakes();
        QVERIFY(open);
        Machine* machine = open->machine;
        const QString dir = open->dir;
        MachineBackupRun* backup = machine->window()->backUpTo(dir, QStringLiteral("before"));
        QVERIFY(waitDone(backup));
        QCOMPARE(backup->progress()->resultLine(kLeft), QStringLiteral("saved: 3 registers"));
        QCOMPARE(backup->progress()->resultLine(kRight), QStringLiteral("saved: 5 registers"));
        const MachineManifest manifest = manifestIn(dir);
        QCOMPARE(manifest.devices.size(), 2);
        QStringList serials;
        for (const ManifestEntry& entry : manifest.devices)
            serials << entry.identity.value(QStringLiteral("serial"));
        QCOMPARE(serials, (QStringList{QStringLiteral("1"), QStringLiteral("2")}));

        MachineBackupRun* verify = machine->window()->verifyFrom(dir);
        QVERIFY(waitDone(verify));
        for (const QString& name : {kLeft, kRight})
            QVERIFY2(verify->progress()->resultLine(name).startsWith(QLatin1String("equal: ")),
                     qPrintable(verify->progress()->resultLine(name)));

        // R2 of the left device changes behind CamBench's back.
        QVERIFY(onDevice<qint32>(
            *machine, kLeft, [](fake::FakeDevice& device) { return device.writeRegister(2, 77); }));
        MachineBackupRun* differs = machine->window()->verifyFrom(dir);
        QVERIFY(waitDone(differs));
        QCOMPARE(differs->progress()->resultLine(kLeft),
                 QString::fromUtf8("1 difference:\nleft: R2 102 → 77"));
        QVERIFY(differs->progress()->resultLine(kRight).startsWith(QLatin1String("equal: ")));

        // Restored after the one question that lists each device's plan.
        QString plans;
        NextDialog<QMessageBox> answer([&](QMessageBox* box) {
            plans = box->detailedText();
            for (QAbstractButton* button : box->buttons())
                if (box->buttonRole(button) == QMessageBox::DestructiveRole) button->click();
        });
        MachineBackupRun* restore = machine->window()->restoreFrom(dir);
        QVERIFY(waitDone(restore));
        QVERIFY2(plans.contains(QLatin1String("R2")), qPrintable(plans));
        for (const QString& name : {kLeft, kRight})
            QVERIFY2(
                restore->progress()->resultLine(name).startsWith(QLatin1String("restored: ")),
                qPrintable(name + QLatin1String(": ") + restore->progress()->resultLine(name)));
        const Result<qint32> r2 = onDevice<qint32>(
            *machine, kLeft, [](fake::FakeDevice& device) { return device.readRegister(2); });
        QCOMPARE(r2 ? *r2 : -1, 102);
    }

    // A backup whose right device was another (its serial in the manifest
    // changed): not restored when the person does not accept it, and said
    // so; the left one's restore cancelled at the one question writes
    // nothing and says so.
    void aSwappedDeviceIsNotRestored() {
        const std::unique_ptr<OpenedMachine> open = openTwoFakes();
        QVERIFY(open);
        Machine* machine = open->machine;
        const QString dir = open->dir;
        QVERIFY(waitDone(machine->window()->backUpTo(dir, {})));
        MachineManifest manifest = manifestIn(dir);
        for (ManifestEntry& entry : manifest.devices)
            if (entry.name == kRight)
                entry.identity.set(QStringLiteral("serial"), QStringLiteral("3"));
        QVERIFY(rewriteManifest(dir, manifest));
        QVERIFY(onDevice<qint32>(
            *machine, kLeft, [](fake::FakeDevice& device) { return device.writeRegister(1, 5); }));

        const DeclineEveryQuestion declining;
        MachineBackupRun* restore = machine->window()->restoreFrom(dir);
        QVERIFY(waitDone(restore));
        QCOMPARE(declining.asked(), (QStringList{QStringLiteral("replacementQuestion"),
                                                 QStringLiteral("machineRestoreQuestion")}));
        const QString right = restore->progress()->resultLine(kRight);
        QVERIFY2(right.startsWith(QLatin1String("not restored: another device answers")),
                 qPrintable(right));
        QCOMPARE(restore->progress()->resultLine(kLeft),
                 QStringLiteral("not restored: cancelled, nothing was written"));
        const Result<qint32> r1 = onDevice<qint32>(
            *machine, kLeft, [](fake::FakeDevice& device) { return device.readRegister(1); });
        QCOMPARE(r1 ? *r1 : -1, 5);  // as it was: nothing was written
    }

    void versionsComparedDeviceByDeviceAndReleased() {
        const std::unique_ptr<OpenedMachine> open = openTwoFakes();
        QVERIFY(open);
        Machine* machine = open->machine;
        const Result<MachineArchive> archive =
            MachineArchive::openOrCreate(open->folder.filePath(QStringLiteral("archive")));
        QVERIFY(archive.ok());
        const Result<usecases::VersionStored> first =
            storeVersion(machine, *archive, QStringLiteral("commissioning"));
        QVERIFY2(first.ok() && first->stored, qPrintable(first.error().message));
        QVERIFY(onDevice<qint32>(
            *machine, kRight, [](fake::FakeDevice& device) { return device.writeRegister(4, 9); }));
        const Result<usecases::VersionStored> second =
            storeVersion(machine, *archive, QStringLiteral("new stroke"));
        QVERIFY2(second.ok() && second->stored, qPrintable(second.error().message));

        MachineHistoryDialog dialog(machine, archive->dir());
        dialog.show();
        QTreeWidget* list = dialog.versionList();
        QCOMPARE(list->topLevelItemCount(), 2);
        QTreeWidgetItem* newest = list->topLevelItem(0);
        QCOMPARE(newest->text(MachineHistoryDialog::Note), QStringLiteral("new stroke"));
        QCOMPARE(newest->childCount(), 1);  // only the right device changed
        QCOMPARE(newest->child(0)->text(MachineHistoryDialog::Note),
                 QString::fromUtf8("right: R4 204 → 9"));

        selectVersions(list, {0, 1});
        dialog.compareButton()->click();
        const QStringList rows = rowsOf(dialog.differenceTable());
        QCOMPARE(rows, (QStringList{QStringLiteral("left||||equal"),
                                    QString::fromUtf8("right|R4|204|9|R4 204 → 9")}));

        // The first against the devices now, read from them.
        selectVersions(list, {1});
        QSignalSpy finished(&dialog, &MachineHistoryDialog::finished);
        dialog.compareNowButton()->click();
        QVERIFY(finished.wait(kDeviceTimeoutMs));
        QVERIFY2(rowsOf(dialog.differenceTable())
                     .contains(QString::fromUtf8("right|R4|204|9|R4 204 → 9")),
                 qPrintable(rowsOf(dialog.differenceTable()).join(u'\n')));

        selectVersions(list, {1});
        dialog.releaseButton()->click();
        QCOMPARE(*archive->released(), first->id);
    }
};

QTEST_MAIN(TestMachineShell)
#include "tst_machine_shell.moc"
