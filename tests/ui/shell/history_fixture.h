#pragma once

// What the tests of a machine's versions share (Machine -> History...): a
// job on one device, a version of every device stored as the command line
// stores it, and the history dialog's lists read as a person reads them.

#include "shell_fixture.h"

#include "comm/device/device_connection.h"
#include "comm/usecases/machine_backup.h"
#include "comm/usecases/machine_history.h"
#include "model/atomic_file.h"
#include "model/machine/machine_archive.h"
#include "model/machine/machine_backup_folder.h"
#include "model/machine/machine_file.h"
#include "ui/device_session.h"
#include "ui/machine/machine.h"
#include "ui/machine/machine_unit.h"

#include <QDir>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTreeWidget>

#include <optional>

namespace cambench::test {

// Waits for `result` of a job on `unit`'s worker.
template <class Device, class T>
inline std::optional<Result<T>> runOn(MachineUnit* unit, DeviceSession::Work<Device, T> work) {
    std::optional<Result<T>> answer;
    QObject context;
    unit->session()->run<Device, T>(&context, QStringLiteral("test"), std::move(work),
                                    [&answer](Result<T> result) { answer = std::move(result); });
    if (!QTest::qWaitFor([&answer] { return answer.has_value(); }, kDeviceTimeoutMs)) return {};
    return answer;
}

// Every device backed up into a new folder and stored as a version of
// `archive` (what `machine backup --archive` does on the command line).
inline Result<usecases::VersionStored> storeVersion(Machine* machine, const MachineArchive& archive,
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

// Every device on the line, its lamp lit and its start reads done.
inline bool waitConnected(const Machine& machine) {
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

// The history list's rows `rows` selected, as a person's clicks do.
inline void selectVersions(QTreeWidget* list, const QList<int>& rows) {
    list->clearSelection();
    for (int row : rows) list->topLevelItem(row)->setSelected(true);
}

// Each row of `table` as its cells' texts joined by '|'.
inline QStringList rowsOf(const QTableWidget* table) {
    QStringList rows;
    for (int row = 0; row < table->rowCount(); ++row) {
        QStringList cells;
        for (int column = 0; column < table->columnCount(); ++column)
            cells << (table->item(row, column) ? table->item(row, column)->text() : QString());
        rows << cells.join(u'|');
    }
    return rows;
}

}  // namespace cambench::test
