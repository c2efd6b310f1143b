#include "machine_history.h"

#include "comm/usecases/machine_backup.h"
#include "model/file_read.h"
#include "model/machine/volatile_items.h"

#include <QCoreApplication>
#include <QDir>

namespace cambench::usecases {

namespace {

// Items a device's line names before it says "and N more".
constexpr int kItemsPerLine = 8;

// A device's options as text ("port /dev/ttyUSB0, protocol standard").
QString optionsText(const MachineDevice& device) {
    QStringList parts;
    for (const auto& [key, value] : device.options) parts << key + u' ' + value;
    return parts.join(QLatin1String(", "));
}

// The machine file's own changes between two states: the machine's name,
// each device's family, options and volatile items (its contents and
// identity are the devices' lines).
QStringList machineFileChanges(const MachineFile& older, const MachineFile& newer) {
    QStringList lines;
    if (older.machine != newer.machine)
        lines << QCoreApplication::translate("cambench::usecases", "machine name %1 → %2")
                     .arg(older.machine, newer.machine);
    for (const MachineDevice& device : newer.devices) {
        const MachineDevice* before = older.device(device.name);
        if (!before) continue;  // an added device is its own line
        if (before->family != device.family)
            lines << QCoreApplication::translate("cambench::usecases", "%1: family %2 → %3")
                         .arg(device.name, before->family, device.family);
        if (before->options != device.options)
            lines << QCoreApplication::translate("cambench::usecases", "%1: %2 → %3")
                         .arg(device.name, optionsText(*before), optionsText(device));
        if (before->volatileItems != device.volatileItems)
            lines << QCoreApplication::translate("cambench::usecases", "%1: volatile items %2 → %3")
                         .arg(device.name, before->volatileItems.join(u' '),
                              device.volatileItems.join(u' '));
    }
    return lines;
}

QStringList volatileItemsOf(const MachineFile& older, const MachineFile& newer,
                            const QString& name) {
    QStringList items;
    for (const MachineFile* machine : {&older, &newer})
        if (const MachineDevice* device = machine->device(name)) items << device->volatileItems;
    return items;
}

// One device present in both states.
DeviceChange compareDevice(const MachineFolderRead& older, const MachineFolderRead& newer,
                           const QString& name) {
    DeviceChange change;
    change.name = name;
    const ManifestEntry* before = older.manifest.entry(name);
    const ManifestEntry* after = newer.manifest.entry(name);
    if (!before || !before->saved() || !after || !after->saved()) {
        const bool olderLacks = !before || !before->saved();
        const ManifestEntry* lacking = olderLacks ? before : after;
        change.kind = DeviceChange::Kind::NotSaved;
        change.why = QCoreApplication::translate("cambench::usecases", "not saved in %1%2")
                         .arg(olderLacks ? older.dir : newer.dir,
                              lacking ? QStringLiteral(" (%1)").arg(lacking->result) : QString());
        return change;
    }
    const Result<BackupComparison> compared =
        diffMachineDevice(*before, older.dir, *after, newer.dir);
    if (!compared) {
        change.kind = DeviceChange::Kind::NotCompared;
        change.why = compared.error().message;
        return change;
    }
    change.differences =
        withoutVolatile(compared->differences, volatileItemsOf(older.machine, newer.machine, name),
                        &change.volatileLeftOut);
    if (before->identity.known() && after->identity.known() && before->identity != after->identity)
        change.identity =
            QCoreApplication::translate("cambench::usecases", "another device: %1 → %2")
                .arg(before->identity.text(), after->identity.text());
    change.kind = change.differences.isEmpty() && change.identity.isEmpty()
                      ? DeviceChange::Kind::Equal
                      : DeviceChange::Kind::Changed;
    return change;
}

// The part of `keys` before their last ", " when all share it ("program
// 3" of "program 3, output 2" and "program 3, output 7"); empty when none.
QString sharedHead(const QStringList& keys) {
    QString head;
    for (const QString& key : keys) {
        const qsizetype at = key.lastIndexOf(QLatin1String(", "));
        const QString mine = at < 0 ? QString() : key.left(at);
        if (mine.isEmpty() || (!head.isEmpty() && mine != head)) return {};
        head = mine;
    }
    return head;
}

}  // namespace

Result<MachineFolderRead> readMachineFolder(const QString& dir) {
    const QString machinePath = QDir(dir).filePath(kMachineBackupFile);
    const Result<QByteArray> machineBytes = readFileBytes(machinePath);
    if (!machineBytes)
        return Error::invalidData(
            QCoreApplication::translate("cambench::usecases",
                                        "%1 is no machine backup folder: %2 (made by `machine "
                                        "backup`)")
                .arg(dir, machineBytes.error().message));
    const Result<MachineFile> machine = parseMachineFile(*machineBytes, machinePath);
    if (!machine) return machine.error();
    const QString manifestPath = QDir(dir).filePath(kMachineManifestFile);
    const Result<QByteArray> manifestBytes = readFileBytes(manifestPath);
    if (!manifestBytes) return manifestBytes.error();
    const Result<MachineManifest> manifest = parseManifest(*manifestBytes, manifestPath);
    if (!manifest) return manifest.error();
    return MachineFolderRead{dir, *machine, *manifest};
}

bool MachineChanges::changed() const {
    if (!machineFile.isEmpty()) return true;
    for (const DeviceChange& device : devices)
        if (device.kind == DeviceChange::Kind::Changed ||
            device.kind == DeviceChange::Kind::Added || device.kind == DeviceChange::Kind::Removed)
            return true;
    return false;
}

bool MachineChanges::complete() const {
    for (const DeviceChange& device : devices)
        if (device.kind == DeviceChange::Kind::NotSaved ||
            device.kind == DeviceChange::Kind::NotCompared)
            return false;
    return true;
}

QStringList MachineChanges::lines() const {
    QStringList lines;
    for (const DeviceChange& device : devices)
        if (const QString line = changeLine(device); !line.isEmpty()) lines << line;
    if (!machineFile.isEmpty())
        lines << QCoreApplication::translate("cambench::usecases", "machine file: %1")
                     .arg(machineFile.join(QLatin1String("; ")));
    return lines;
}

QString changeLine(const DeviceChange& change) {
    switch (change.kind) {
        case DeviceChange::Kind::Equal:
        case DeviceChange::Kind::NotSaved:
        case DeviceChange::Kind::NotCompared:
            return {};
        case DeviceChange::Kind::Added:
            return change.why.isEmpty()
                       ? QCoreApplication::translate("cambench::usecases", "%1: added")
                             .arg(change.name)
                       : QCoreApplication::translate("cambench::usecases", "%1: added (%2)")
                             .arg(change.name, change.why);
        case DeviceChange::Kind::Removed:
            return QCoreApplication::translate("cambench::usecases", "%1: taken out of the machine")
                .arg(change.name);
        case DeviceChange::Kind::Changed:
            break;
    }
    QStringList parts;
    if (!change.identity.isEmpty()) parts << change.identity;
    if (change.differences.size() == 1) {
        parts << change.differences.first().text;
    } else if (!change.differences.isEmpty()) {
        QStringList keys;
        for (const BackupDifference& difference : change.differences)
            if (!keys.contains(difference.key)) keys << difference.key;
        const QString head = sharedHead(keys);
        QStringList named;
        for (const QString& key : keys.mid(0, kItemsPerLine))
            named << (head.isEmpty() ? key : key.mid(head.size() + 2));
        QString items = named.join(QLatin1String(", "));
        if (keys.size() > kItemsPerLine)
            items += QCoreApplication::translate("cambench::usecases", " and %1 more")
                         .arg(keys.size() - kItemsPerLine);
        parts << (head.isEmpty() ? items : head + QStringLiteral(": ") + items);
    }
    return change.name + QStringLiteral(": ") + parts.join(QLatin1String("; "));
}

QList<BackupDifference> withoutVolatile(const QList<BackupDifference>& differences,
                                        const QStringList& items, int* leftOut) {
    QList<BackupDifference> kept;
    int volatileCount = 0;
    for (const BackupDifference& difference : differences) {
        if (isVolatileItem(items, difference.key))
            ++volatileCount;
        else
            kept << difference;
    }
    if (leftOut) *leftOut = volatileCount;
    return kept;
}

namespace {

// Two states read, device by device, then the machine file's own changes.
MachineChanges compareStates(const MachineFolderRead& before, const MachineFolderRead& after) {
    MachineChanges changes;
    for (const MachineDevice& device : after.machine.devices) {
        if (before.machine.device(device.name)) {
            changes.devices << compareDevice(before, after, device.name);
            continue;
        }
        DeviceChange added;
        added.name = device.name;
        added.kind = DeviceChange::Kind::Added;
        if (const ManifestEntry* entry = after.manifest.entry(device.name))
            added.why = entry->summary;
        changes.devices << added;
    }
    for (const MachineDevice& device : before.machine.devices)
        if (!after.machine.device(device.name))
            changes.devices << DeviceChange{device.name, DeviceChange::Kind::Removed, {}, 0, {},
                                            {}};
    changes.machineFile = machineFileChanges(before.machine, after.machine);
    return changes;
}

// The one line of a machine folder that could not be read.
MachineChanges unreadable(const Error& error) {
    DeviceChange machine;
    machine.name = QCoreApplication::translate("cambench::usecases", "machine");
    machine.kind = DeviceChange::Kind::NotCompared;
    machine.why = error.message;
    MachineChanges changes;
    changes.devices << machine;
    return changes;
}

}  // namespace

MachineChanges compareMachineFolders(const QString& older, const QString& newer) {
    const Result<MachineFolderRead> before = readMachineFolder(older);
    const Result<MachineFolderRead> after = readMachineFolder(newer);
    if (!before || !after) return unreadable((!before ? before : after).error());
    return compareStates(*before, *after);
}

MachineChanges compareWithDevicesNow(const QString& version, const MachineFolderRead& now) {
    const Result<MachineFolderRead> released = readMachineFolder(version);
    if (!released) return unreadable(released.error());
    MachineChanges changes = compareStates(*released, now);
    changes.machineFile.clear();
    for (DeviceChange& change : changes.devices) {
        if (change.kind != DeviceChange::Kind::NotSaved) continue;
        const ManifestEntry* read = now.manifest.entry(change.name);
        if (read && read->saved()) {
            const ManifestEntry* kept = released->manifest.entry(change.name);
            change.why =
                QCoreApplication::translate("cambench::usecases", "not saved in the version%1")
                    .arg(kept ? QStringLiteral(" (%1)").arg(kept->result) : QString());
        } else
            change.why =
                read ? QCoreApplication::translate("cambench::usecases", "its backup now %1")
                           .arg(read->result)
                     : QCoreApplication::translate("cambench::usecases",
                                                   "not read from the device now");
    }
    return changes;
}

MachineChanges firstVersionOf(const QString& folder) {
    MachineChanges changes;
    const Result<MachineFolderRead> read = readMachineFolder(folder);
    if (!read) return changes;
    for (const ManifestEntry& entry : read->manifest.devices) {
        DeviceChange first;
        first.name = entry.name;
        first.kind = DeviceChange::Kind::Added;
        first.why = entry.summary.isEmpty()
                        ? QCoreApplication::translate("cambench::usecases", "first version")
                        : QCoreApplication::translate("cambench::usecases", "first version: %1")
                              .arg(entry.summary);
        changes.devices << first;
    }
    return changes;
}

Result<VersionFolder> takeOutVersion(const MachineArchive& archive, const QString& id) {
    VersionFolder version{id, std::make_unique<QTemporaryDir>()};
    if (!version.folder->isValid())
        return Error::invalidData(
            QCoreApplication::translate("cambench::usecases",
                                        "No temporary folder to take version %1 out of %2 into: %3")
                .arg(id.left(10), archive.dir(), version.folder->errorString()));
    if (const Status taken = archive.extract(id, version.path()); !taken) return taken.error();
    return version;
}

Result<VersionStored> storeMachineVersion(const MachineArchive& archive, const QString& staged,
                                          const BackupAuthor& author) {
    const Result<MachineFolderRead> read = readMachineFolder(staged);
    if (!read) return read.error();
    QStringList files{kMachineBackupFile, kMachineManifestFile};
    QStringList notSaved;
    for (const MachineDevice& device : read->machine.devices) {
        const ManifestEntry* entry = read->manifest.entry(device.name);
        if (!entry || !entry->saved())
            notSaved << device.name;
        else
            files << entry->file;
    }
    if (!notSaved.isEmpty())
        return Error::communication(
            QCoreApplication::translate(
                "cambench::usecases",
                "%1 not saved: no version was stored (a version without a device would read as "
                "the device taken out of the machine).")
                .arg(notSaved.join(QLatin1String(", "))));
    const Result<QList<ArchiveVersion>> versions = archive.versions();
    if (!versions) return versions.error();
    VersionStored stored;
    if (versions->isEmpty()) {
        stored.changes = firstVersionOf(staged);
    } else {
        const Result<VersionFolder> latest = takeOutVersion(archive, versions->first().id);
        if (!latest) return latest.error();
        stored.changes = compareMachineFolders(latest->path(), staged);
        if (!stored.changes.complete()) {
            QStringList why;
            for (const DeviceChange& device : stored.changes.devices)
                if (!device.why.isEmpty() && device.kind != DeviceChange::Kind::Added)
                    why << QStringLiteral("%1: %2").arg(device.name, device.why);
            return Error::invalidData(
                QCoreApplication::translate(
                    "cambench::usecases",
                    "The backup could not be compared with the latest version, no version was "
                    "stored: %1")
                    .arg(why.join(QLatin1String("; "))));
        }
        if (!stored.changes.changed()) return stored;
    }
    const Result<QString> id =
        archive.store(staged, files, {author.operatorName, author.note, stored.changes.lines()});
    if (!id) return id.error();
    stored.stored = true;
    stored.id = *id;
    return stored;
}

}  // namespace cambench::usecases
