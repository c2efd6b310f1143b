// Issue 37, item 4: Machine → History… with real widgets, a CamCon and an
// MC200 each on its own in-process simulated device. Two versions are
// stored (the second after a variable and a volatile counter of the MC200
// changed); the dialog lists both with what changed in each, compares the
// two device by device (the counter left out), compares the first with
// the devices now, and marks the first released - a tag that plain git
// and the archive read back.
#include "shell_fixture.h"

#include "comm/device/device_connection.h"
#include "comm/mc1/mc1_device.h"
#include "comm/usecases/machine_backup.h"
#include "comm/usecases/machine_history.h"
#include "model/atomic_file.h"
#include "model/machine/machine_archive.h"
#include "model/machine/machine_backup_folder.h"
#include "model/machine/machine_file.h"
#include "ui/device_session.h"
#include "ui/machine/machine.h"
#include "ui/machine/machine_history_dialog.h"
#include "ui/machine/machine_unit.h"

#include <QDir>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTreeWidget>

using namespace cambench;
using namespace cambench::test;

namespace {

// A CamCon and an MC200 V2 whose V100-V199 are counters.
MachineFile press() {
    MachineFile file;
    file.machine = QStringLiteral("History press");
    file.devices << MachineDevice{QStringLiteral("cams"),
                                  QStringLiteral("camcon"),
                                  {{QStringLiteral("port"), QStringLiteral("sim:throttle=0")},
                                   {QStringLiteral("protocol"), QStringLiteral("standard")}},
                                  {},
                                  {}}
                 << MachineDevice{QStringLiteral("press-plc"),
                                  QStringLiteral("mc1"),
                                  {{QStringLiteral("port"), QStringLiteral("sim:variant=mc200v2")},
                                   {QStringLiteral("protocol"), QStringLiteral("mc1")},
                                   {QStringLiteral("variant"), QStringLiteral("mc200v2")}},
                                  {},
                                  {QStringLiteral("V100-V199")}};
    return file;
}

// Waits for `result` of a job on `unit`'s worker.
template <class Device, class T>
std::optional<Result<T>> runOn(MachineUnit* unit, DeviceSession::Work<Device, T> work) {
    std::optional<Result<T>> answer;
    QObject context;
    unit->session()->run<Device, T>(&context, QStringLiteral("test"), std::move(work),
                                    [&answer](Result<T> result) { answer = std::move(result); });
    if (!QTest::qWaitFor([&answer] { return answer.has_value(); }, kDeviceTimeoutMs)) return {};
    return answer;
}

// Every device backed up into a new folder and stored as a version of
// `archive` (what `machine backup --archive` does on the command line).
Result<usecases::VersionStored> storeVersion(Machine* machine, const MachineArchive& archive,
                                             const QString& note) {
    QTemporaryDir staged;
    MachineManifest manifest;
    manifest.machine = machine->name();
    manifest.author = BackupAuthor{QStringLiteral("tester"), note, {}, {}};
    MachineFile file = machine->file();
    for (MachineUnit* unit : machine->units()) {
        const MachineDevice device = unit->device();
        const auto taken = runOn<comm::DeviceConnection, usecases::DeviceBackedUp>(
            unit, [&](comm::DeviceConnection&, comm::JobContext& job) {
                return Result<usecases::DeviceBackedUp>(
                    usecases::backUpMachineDevice(job, device, staged.path(), false));
            });
        if (!taken || !*taken) return Error::communication(QStringLiteral("no backup"));
        manifest.devices << (*taken)->entry;
    }
    if (!writeFileAtomically(QDir(staged.path()).filePath(kMachineBackupFile),
                             machineFileJson(file)) ||
        !writeFileAtomically(QDir(staged.path()).filePath(kMachineManifestFile),
                             manifestJson(manifest)))
        return Error::invalidData(QStringLiteral("not written"));
    return usecases::storeMachineVersion(archive, staged.path(), manifest.author);
}

bool writeVariable(MachineUnit* plc, int number, qint64 value) {
    const auto written =
        runOn<comm::Mc1Device, Done>(plc, [=](comm::Mc1Device& device, comm::JobContext&) {
            return device.writeVariable(number, value);
        });
    return written && *written;
}

bool waitConnected(const Machine& machine) {
    return QTest::qWaitFor(
        [&machine] {
            for (const MachineUnit* unit : machine.units())
                if (unit->lamp() != MachineUnit::Lamp::Connected ||
                    !unit->session()->deviceChecked())
                    return false;
            return true;
        },
        kDeviceTimeoutMs);
}

void selectVersions(QTreeWidget* list, const QList<int>& rows) {
    list->clearSelection();
    for (int row : rows) list->topLevelItem(row)->setSelected(true);
}

QStringList rowsOf(const QTableWidget* table) {
    QStringList rows;
    for (int row = 0; row < table->rowCount(); ++row) {
        QStringList cells;
        for (int column = 0; column < table->columnCount(); ++column)
            cells << (table->item(row, column) ? table->item(row, column)->text() : QString());
        rows << cells.join(u'|');
    }
    return rows;
}

}  // namespace

class TestMachineHistory : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { useTestSettings(); }

    void versionsComparedAndReleased() {
        Shell shell;
        Machine* machine = shell.openMachine(press(), {});
        QVERIFY(waitConnected(*machine));
        MachineUnit* plc = machine->unit(QStringLiteral("press-plc"));
        // Connected, the device's line is rebuilt from its connection: the
        // items that change by themselves stay the file's.
        QCOMPARE(machine->file().devices.at(1).volatileItems, QStringList{"V100-V199"});
        QTemporaryDir work;
        const Result<MachineArchive> archive =
            MachineArchive::openOrCreate(work.filePath(QStringLiteral("archive")));
        QVERIFY(archive.ok());

        const Result<usecases::VersionStored> first =
            storeVersion(machine, *archive, QStringLiteral("commissioning"));
        QVERIFY2(first.ok() && first->stored, qPrintable(first.error().message));
        QVERIFY(writeVariable(plc, 12, 4711));
        QVERIFY(writeVariable(plc, 150, 99));  // a counter: never a difference
        const Result<usecases::VersionStored> second =
            storeVersion(machine, *archive, QStringLiteral("new stroke"));
        QVERIFY2(second.ok() && second->stored, qPrintable(second.error().message));

        MachineHistoryDialog dialog(machine, archive->dir());
        dialog.show();
        QTreeWidget* list = dialog.versionList();
        QCOMPARE(list->topLevelItemCount(), 2);
        QTreeWidgetItem* newest = list->topLevelItem(0);
        QCOMPARE(newest->text(MachineHistoryDialog::Version), second->id.left(10));
        QCOMPARE(newest->text(MachineHistoryDialog::Note), QStringLiteral("new stroke"));
        QCOMPARE(newest->text(MachineHistoryDialog::Author), QStringLiteral("tester"));
        QCOMPARE(newest->childCount(), 1);  // only the MC200 changed
        QCOMPARE(newest->child(0)->text(MachineHistoryDialog::Note),
                 QStringLiteral("press-plc: V12 0 → 4711"));
        QVERIFY(list->topLevelItem(1)->childCount() == 2);  // the first: every device

        // The two compared: the MC200's V12, nothing of the CamCon, the counter left out.
        selectVersions(list, {0, 1});
        QVERIFY(dialog.compareButton()->isEnabled());
        QVERIFY(!dialog.restoreButton()->isEnabled());
        dialog.compareButton()->click();
        const QStringList rows = rowsOf(dialog.differenceTable());
        QVERIFY2(rows.contains(QStringLiteral("cams||||equal")), qPrintable(rows.join(u'\n')));
        QVERIFY2(rows.contains(QStringLiteral("press-plc|V12|0|4711|V12 0 → 4711")),
                 qPrintable(rows.join(u'\n')));
        QCOMPARE(rows.size(), 2);
        QVERIFY2(dialog.statusLabel()->text().contains(QLatin1String("differences in "
                                                                     "press-plc")),
                 qPrintable(dialog.statusLabel()->text()));

        // The first against the devices now: the MC200 differs, read from the device.
        selectVersions(list, {1});
        QSignalSpy finished(&dialog, &MachineHistoryDialog::finished);
        dialog.compareNowButton()->click();
        QVERIFY(finished.wait(kDeviceTimeoutMs));
        const QStringList now = rowsOf(dialog.differenceTable());
        QVERIFY2(now.contains(QStringLiteral("press-plc|V12|0|4711|V12 0 → 4711")),
                 qPrintable(now.join(u'\n')));
        QVERIFY2(now.contains(QStringLiteral("cams||||equal")), qPrintable(now.join(u'\n')));

        // Marked released: the first is the one that should be on the machine.
        selectVersions(list, {1});
        dialog.releaseButton()->click();
        QCOMPARE(*archive->released(), first->id);
        QCOMPARE(list->topLevelItem(1)->text(MachineHistoryDialog::Released),
                 QStringLiteral("released, released-1"));
        QCOMPARE(list->topLevelItem(0)->text(MachineHistoryDialog::Released), QString());
    }
};

QTEST_MAIN(TestMachineHistory)
#include "tst_machine_history.moc"
