// `machine backup FILE -o DIR`, `machine verify DIR`, `machine restore DIR`,
// `machine diff DIR1 DIR2`: each device of the machine through its family's
// typed backup part (usecases::FamilyBackup, registered by its FamilyParts;
// comm/usecases/machine_backup.h asks the device who it is first), devices
// on different ports at once (machine_parallel.h), each device's lines
// printed whole in the file's order. The folder (model/machine/
// machine_backup_folder.h) holds the machine file (machine.json; at the
// end with each saved device's identity), one file per device and
// manifest.json, rewritten after each device: who took it, why and with
// what, and per device its name, family, identity, what it said of itself,
// file, SHA-256, time and result. Another device than the machine file or
// the backup records is said ("another device answers: expected ...,
// found ...") and nothing is saved from it, verified or written to it
// unless the person named it with --replacement. A restore's safety
// copies go to a folder beside the backup folder, with a manifest of their
// own. Names no family: the words of each difference are the family's.
#include "machine_command.h"
#include "machine_history.h"

#include "backup_output.h"
#include "cli_output.h"
#include "cli_session.h"
#include "exit_codes.h"
#include "machine_parallel.h"
#include "outcome_output.h"

#include "comm/usecases/machine_backup.h"
#include "model/atomic_file.h"
#include "model/file_read.h"

#include <QDir>

#include <functional>
#include <optional>
#include <vector>

namespace cambench::cli {

namespace {

using usecases::BackupComparison;
using usecases::DeviceChecked;

QString exitText(int code) {
    switch (code) {
        case ExitDevice:
            return QStringLiteral("exit 1: the device refused or differs");
        case ExitUsage:
            return QStringLiteral("exit 2: the family's part does not fit this device");
        case ExitCommunication:
            return QStringLiteral("exit 3: not reached or the line failed");
        case ExitInvalidData:
            return QStringLiteral("exit 4: a file or value failed its check");
        default:
            return QStringLiteral("exit %1").arg(code);
    }
}

// The machine file and the manifest a backup left in `dir`.
struct MachineFolder {
    QString dir;
    MachineSetup setup;
    MachineManifest manifest;
};

Result<MachineFolder> loadFolder(const QString& dir) {
    const Result<usecases::MachineFolderRead> read = usecases::readMachineFolder(dir);
    if (!read) return read.error();
    const Result<MachineSetup> setup =
        machineSetup(read->machine, QDir(dir).filePath(kMachineBackupFile));
    if (!setup) return setup.error();
    return MachineFolder{dir, *setup, read->manifest};
}

// "another device answers: ... NAME." on stderr, as the device's own
// lines say it.
void sayAnotherDevice(const QString& name, const QString& another, const QString& nothing) {
    reportError(Error::invalidData(
        QStringLiteral("%1: %2. %3. Only if it replaces that device, add --replacement %1.")
            .arg(name, another, nothing)));
}

ManifestEntry backUp(const MachineDevice& device, const GlobalOptions& options, const QString& dir,
                     bool replacement) {
    CliSession session(options);
    printOut(QStringLiteral("== %1 (%2, %3)\n").arg(device.name, device.family, session.where()));
    const Result<usecases::DeviceBackedUp> done =
        session.run<comm::DeviceConnection, usecases::DeviceBackedUp>(
            QStringLiteral("back up %1").arg(device.name),
            [&device, dir, replacement](comm::DeviceConnection&,
                                        comm::JobContext& job) -> Result<usecases::DeviceBackedUp> {
                return usecases::backUpMachineDevice(job, device, dir, replacement);
            });
    // Connecting failed: the job never ran.
    if (!done) {
        reportError(done.error());
        ManifestEntry entry;
        entry.name = device.name;
        entry.family = device.family;
        entry.file = deviceFileName(device.name);
        entry.result = QStringLiteral("failed: not reached: %1").arg(done.error().message);
        return entry;
    }
    if (done->checked && !done->checked->another.isEmpty())
        sayAnotherDevice(device.name, done->checked->another,
                         QStringLiteral("Nothing was saved from it"));
    else if (done->error.kind != ErrorKind::None)
        reportError(done->error);
    else
        printOut(QStringLiteral("saved %1 to %2\n")
                     .arg(done->entry.summary, QDir(dir).filePath(done->entry.file)));
    return done->entry;
}

// The machine file with the identity each saved device answered with.
MachineFile withIdentities(MachineFile machine, const QList<ManifestEntry>& entries) {
    for (const ManifestEntry& entry : entries) {
        if (!entry.saved()) continue;
        for (MachineDevice& device : machine.devices)
            if (device.name == entry.name) device.identity = entry.identity;
    }
    return machine;
}

// Records in the person's machine file each identity first seen (and the
// replacements accepted): the next status, backup or verify says when
// another device answers there. A file that cannot be written is said, and
// the backup is not failed for it.
void recordIdentities(const MachineFile& given, const MachineFile& now, const QString& path,
                      const QStringList& replacements) {
    MachineFile updated = given;
    QStringList recorded;
    for (int i = 0; i < updated.devices.size(); ++i) {
        MachineDevice& device = updated.devices[i];
        const DeviceIdentity& seen = now.devices.at(i).identity;
        if (!seen.known() || device.identity == seen) continue;
        if (device.identity.known() && !replacements.contains(device.name)) continue;
        device.identity = seen;
        recorded << device.name;
    }
    if (recorded.isEmpty()) return;
    if (const Status written = writeFileAtomically(path, machineFileJson(updated)); !written) {
        printError(QStringLiteral("note: the identities of %1 were not recorded in %2: %3")
                       .arg(recorded.join(QLatin1String(", ")), path, written.error().message));
        return;
    }
    printOut(QStringLiteral("%1 records the identity of %2 now\n")
                 .arg(path, recorded.join(QLatin1String(", "))));
}

}  // namespace

int runMachineBackup(const MachineSetup& setup, const MachineRun& run) {
    const QString& dir = run.dir;
    if (!QDir().mkpath(dir))
        return reportError(Error::communication(
            QStringLiteral("cannot make the folder %1; check the path and its rights").arg(dir)));
    std::optional<MachineManifest> earlier;
    if (run.resume) {
        const Result<MachineFolder> folder = loadFolder(dir);
        if (folder) earlier = folder->manifest;
    }
    // The machine file as given first: an interrupted backup still holds it.
    const QString folderMachine = QDir(dir).filePath(kMachineBackupFile);
    if (const Status saved = writeFileAtomically(folderMachine, machineFileJson(setup.machine));
        !saved)
        return reportError(saved.error());
    const QList<MachineDevice>& all = setup.machine.devices;
    std::vector<std::optional<ManifestEntry>> entries(size_t(all.size()));  // a slot per thread
    QList<int> indices;
    for (int i = 0; i < all.size(); ++i) indices << i;
    const auto backUpOrKeep = [&](int i) {
        const ManifestEntry* before = earlier ? earlier->entry(all.at(i).name) : nullptr;
        if (before && stillSaved(*before, dir)) {
            printOut(QStringLiteral("== %1: kept from the earlier run (%2)\n")
                         .arg(all.at(i).name, before->time.toString(Qt::ISODateWithMs)));
            entries[size_t(i)] = *before;
        } else {
            entries[size_t(i)] = backUp(all.at(i), setup.options.at(i), dir,
                                        run.replacements.contains(all.at(i).name));
        }
    };
    // Rewritten after each device, one at a time, with every device finished
    // so far in the file's order: an interrupted backup says what it has.
    // Only finished devices' slots are read here: the others are still being
    // written by their threads.
    MachineManifest manifest;
    manifest.machine = setup.machine.machine;
    manifest.author = run.author;
    manifest.started = QDateTime::currentDateTimeUtc();
    Status written = success();
    std::vector<bool> finished(size_t(all.size()), false);
    const auto recordDone = [&](int done) {
        finished[size_t(done)] = true;
        manifest.devices.clear();
        for (size_t i = 0; i < entries.size(); ++i)
            if (finished[i]) manifest.devices << *entries[i];
        if (written)
            written = writeFileAtomically(QDir(dir).filePath(kMachineManifestFile),
                                          manifestJson(manifest));
    };
    runDevicesByPort(setup.options, indices, backUpOrKeep, recordDone);
    if (!written) return reportError(written.error());
    const MachineFile identified = withIdentities(setup.machine, manifest.devices);
    if (const Status saved = writeFileAtomically(folderMachine, machineFileJson(identified));
        !saved)
        return reportError(saved.error());
    recordIdentities(setup.machine, identified, run.machinePath, run.replacements);
    int saved = 0;
    for (const ManifestEntry& entry : manifest.devices) saved += entry.saved() ? 1 : 0;
    printOut(QStringLiteral("%1: %2 of %3 devices saved in %4 (by %5%6)\n")
                 .arg(setup.machine.machine)
                 .arg(saved)
                 .arg(all.size())
                 .arg(dir, run.author.operatorName,
                      run.author.note.isEmpty() ? QString()
                                                : QStringLiteral(": \"%1\"").arg(run.author.note)));
    for (const ManifestEntry& entry : manifest.devices)
        if (!entry.saved())
            printOut(QStringLiteral("NOT SAVED: %1: %2\n").arg(entry.name, entry.result));
    return saved == all.size() ? ExitOk : ExitCommunication;
}

namespace {

// What became of one device in a verify or a restore: its exit code and its
// summary line.
struct DeviceOutcome {
    int code = ExitOk;
    QString line;
};

// One device's work of a verify or a restore on its own session: `work`
// runs the checked use case in a job and says what became of it.
using DeviceWork =
    std::function<DeviceOutcome(CliSession& session, const ManifestEntry& entry, bool accepted)>;

// Runs `work` on each device the folder saved (and `only` names, when
// given), devices on different ports at once; the summary and the exit
// code `exitFor` makes of the devices' codes.
int forEachSaved(const MachineFolder& folder, const QStringList& only,
                 const QStringList& replacements, const DeviceWork& work,
                 const std::function<int(const QList<int>&)>& exitFor) {
    for (const auto& [names, option] : {std::pair{only, QStringLiteral("--only")},
                                        std::pair{replacements, QStringLiteral("--replacement")}})
        if (const Status known = checkDeviceNames(folder.setup.machine, names, option); !known)
            return reportError(known.error());
    const QList<MachineDevice>& all = folder.setup.machine.devices;
    std::vector<DeviceOutcome> outcomes(size_t(all.size()));  // a slot per thread
    QList<int> saved;  // the devices to run, in the file's order
    for (int i = 0; i < all.size(); ++i) {
        const MachineDevice& device = all.at(i);
        if (!only.isEmpty() && !only.contains(device.name)) continue;
        const ManifestEntry* entry = folder.manifest.entry(device.name);
        if (!entry || !stillSaved(*entry, folder.dir)) {
            outcomes[size_t(i)] = {
                ExitInvalidData,
                QStringLiteral("%1: not in the backup or its file changed since").arg(device.name)};
            continue;
        }
        saved << i;
    }
    runDevicesByPort(folder.setup.options, saved, [&](int i) {
        const MachineDevice& device = all.at(i);
        CliSession session(folder.setup.options.at(i));
        printOut(
            QStringLiteral("== %1 (%2, %3)\n").arg(device.name, device.family, session.where()));
        outcomes[size_t(i)] =
            work(session, *folder.manifest.entry(device.name), replacements.contains(device.name));
    });
    QStringList summary;
    QList<int> codes;
    for (const DeviceOutcome& outcome : outcomes) {
        if (outcome.line.isEmpty()) continue;  // not asked for (--only)
        summary << outcome.line;
        codes << outcome.code;
    }
    printOut(QStringLiteral("%1:\n%2\n").arg(folder.setup.machine.machine, summary.join('\n')));
    return exitFor(codes);
}

// A device not reached, or whose job failed: said, and its outcome.
DeviceOutcome failedWith(const QString& name, const Error& error, const QString& what) {
    reportError(error);
    const int code = exitCodeFor(error.kind);
    return {code, QStringLiteral("%1: %2 (%3)").arg(name, what, exitText(code))};
}

DeviceOutcome anotherDevice(const QString& name, const DeviceChecked& checked,
                            const QString& nothing) {
    sayAnotherDevice(name, checked.another, nothing);
    return {ExitInvalidData, QStringLiteral("%1: ANOTHER DEVICE: %2").arg(name, checked.another)};
}

// Exit 1 when a device differs; a device not verified is worse.
int verifyExit(const QList<int>& codes) {
    int worst = ExitOk;
    for (int code : codes)
        if (code != ExitOk && code != ExitDevice) worst = code;
    return worst != ExitOk ? worst : codes.contains(ExitDevice) ? ExitDevice : ExitOk;
}

}  // namespace

int runMachineVerify(const QString& dir, const QStringList& replacements) {
    const Result<MachineFolder> folder = loadFolder(dir);
    if (!folder) return reportError(folder.error());
    return forEachSaved(
        *folder, {}, replacements,
        [&dir](CliSession& session, const ManifestEntry& entry, bool accepted) -> DeviceOutcome {
            const Result<usecases::DeviceVerified> verified =
                session.run<comm::DeviceConnection, usecases::DeviceVerified>(
                    QStringLiteral("verify %1").arg(entry.name),
                    [&](comm::DeviceConnection&, comm::JobContext& job) {
                        return usecases::verifyMachineDevice(
                            job, entry, dir,
                            accepted ? ReplacementConsent::any() : ReplacementConsent{});
                    });
            if (!verified)
                return failedWith(entry.name, verified.error(), QStringLiteral("NOT VERIFIED"));
            if (!verified->checked.another.isEmpty())
                return anotherDevice(entry.name, verified->checked,
                                     QStringLiteral("It was not verified"));
            printComparison(verified->comparison);
            if (verified->comparison.equal())
                return {ExitOk, QStringLiteral("%1: equal").arg(entry.name)};
            return {ExitDevice, QStringLiteral("%1: DIFFERS (%2)")
                                    .arg(entry.name)
                                    .arg(verified->comparison.differences.size())};
        },
        verifyExit);
}

int runMachineRestore(const QString& dir, const MachineRun& run) {
    const Result<MachineFolder> folder = loadFolder(dir);
    if (!folder) return reportError(folder.error());
    // The safety copies of this restore: a folder beside the backup's,
    // made when the first device takes one.
    const QString safetyDir = safetyFolderPath(run.safetyBeside.isEmpty() ? dir : run.safetyBeside,
                                               QDateTime::currentDateTimeUtc());
    std::vector<std::optional<ManifestEntry>> copies(size_t(folder->setup.machine.devices.size()));
    const int code = forEachSaved(
        *folder, run.only, run.replacements,
        [&](CliSession& session, const ManifestEntry& entry, bool accepted) -> DeviceOutcome {
            usecases::RestoreRequest request;
            if (accepted) request.replacement = ReplacementConsent::any();
            request.safetyCopy = QDir(safetyDir).filePath(entry.file);
            if (!run.planOnly && !QDir().mkpath(safetyDir))
                return failedWith(
                    entry.name,
                    Error::communication(QStringLiteral("cannot make the folder %1 for the safety "
                                                        "copies: nothing was written")
                                             .arg(safetyDir)),
                    QStringLiteral("NOT RESTORED"));
            if (run.planOnly) {
                const Result<usecases::DevicePlanned> planned =
                    session.run<comm::DeviceConnection, usecases::DevicePlanned>(
                        QStringLiteral("plan %1").arg(entry.name),
                        [&](comm::DeviceConnection&, comm::JobContext& job) {
                            return usecases::planMachineDevice(job, entry, dir, request);
                        });
                if (!planned)
                    return failedWith(entry.name, planned.error(), QStringLiteral("NO PLAN"));
                if (!planned->checked.another.isEmpty())
                    return anotherDevice(entry.name, planned->checked,
                                         QStringLiteral("Nothing would be written to it"));
                QString text;
                for (const QString& step : planned->plan.steps) text += step + QLatin1Char('\n');
                for (const BackupDifference& change : planned->plan.changes)
                    text += QStringLiteral("will write: %1\n").arg(change.line());
                printOut(text);
                return {ExitOk, QStringLiteral("%1: items to change: %2")
                                    .arg(entry.name)
                                    .arg(planned->plan.changes.size())};
            }
            const Result<usecases::DeviceRestored> restored =
                session.run<comm::DeviceConnection, usecases::DeviceRestored>(
                    QStringLiteral("restore %1").arg(entry.name),
                    [&](comm::DeviceConnection&, comm::JobContext& job) {
                        return usecases::restoreMachineDevice(job, entry, dir, request);
                    });
            if (!restored)
                return failedWith(entry.name, restored.error(), QStringLiteral("NOT RESTORED"));
            if (!restored->checked.another.isEmpty())
                return anotherDevice(entry.name, restored->checked,
                                     QStringLiteral("Nothing was written to it"));
            const QString copy = restored->result.safetyCopy;
            if (!copy.isEmpty()) {
                sameModeAs(copy, QDir(dir).filePath(entry.file));
                const ManifestEntry copied = safetyCopyEntry(
                    entry, copy, restored->checked.found.identity, restored->checked.found.text);
                const QList<MachineDevice>& devices = folder->setup.machine.devices;
                for (size_t i = 0; i < copies.size(); ++i)
                    if (devices.at(qsizetype(i)).name == entry.name) copies[i] = copied;
                printOut(QStringLiteral("safety copy of what %1 held: %2\n").arg(entry.name, copy));
            }
            const int tally = printOutcomeTally(restored->result.outcomes);
            if (tally == ExitOk) return {ExitOk, QStringLiteral("%1: restored").arg(entry.name)};
            return {tally,
                    QStringLiteral("%1: NOT RESTORED (%2)").arg(entry.name, exitText(tally))};
        },
        [](const QList<int>& codes) {
            for (int code : codes)
                if (code != ExitOk) return code;
            return int(ExitOk);
        });
    // The safety folder is a backup folder of its own: `machine restore`
    // takes it back.
    QList<ManifestEntry> listed;
    for (const std::optional<ManifestEntry>& copy : copies)
        if (copy) listed << *copy;
    if (const Status written =
            listSafetyCopies(dir, safetyDir, folder->setup.machine, run.author, listed);
        !written) {
        printError(QStringLiteral("the safety copies in %1 are not listed: %2")
                       .arg(safetyDir, written.error().message));
        return code;
    }
    if (!listed.isEmpty())
        printOut(QStringLiteral("safety copies listed in %1\n")
                     .arg(QDir(safetyDir).filePath(kMachineManifestFile)));
    return code;
}

int runMachineDiff(const QString& first, const QString& second) {
    const Result<MachineFolder> one = loadFolder(first);
    if (!one) return reportError(one.error());
    if (const Result<MachineFolder> two = loadFolder(second); !two) return reportError(two.error());
    // The history's comparison (the volatile items left out); where a
    // device is reached is no difference of the device.
    usecases::MachineChanges changes = usecases::compareMachineFolders(first, second);
    changes.machineFile.clear();
    return printMachineChanges(changes, one->setup.machine.machine, ExitInvalidData);
}

}  // namespace cambench::cli
