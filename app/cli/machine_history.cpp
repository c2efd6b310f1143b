// The machine's history on the command line (issue 37). A version is a
// commit of the archive (model/machine/machine_archive.h): `machine backup
// --archive` backs the machine up into the archive's folder with the
// machine backup and stores a version only when a device (or the machine
// file) changed; `watch` backs it up into a temporary folder and compares
// that with the released version. Every comparison is the use case's
// (comm/usecases/machine_history.h), volatile items left out. Names no
// family.
#include "machine_history.h"

#include "cli_output.h"
#include "exit_codes.h"

#include "comm/usecases/machine_history.h"
#include "model/file_read.h"
#include "model/machine/machine_archive.h"

#include <QDir>
#include <QFileInfo>
#include <QTemporaryDir>

namespace cambench::cli {

using usecases::DeviceChange;
using usecases::MachineChanges;

namespace {

QString timeText(const QDateTime& time) {
    return time.toUTC().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss 'UTC'"));
}

// "a1b2c3d4e5 (2026-11-29 05:00:27 UTC, alice: "commissioning")".
QString versionText(const ArchiveVersion& version) {
    const QString note =
        version.note.isEmpty() ? QString() : QStringLiteral(": \"%1\"").arg(version.note);
    return QStringLiteral("%1 (%2, %3%4)")
        .arg(version.shortId(), timeText(version.time), version.author, note);
}

Result<ArchiveVersion> versionOf(const MachineArchive& archive, const QString& id) {
    const Result<QList<ArchiveVersion>> versions = archive.versions();
    if (!versions) return versions.error();
    for (const ArchiveVersion& version : *versions)
        if (version.id == id) return version;
    return Error::usage(QStringLiteral("%1 is no version of %2").arg(id, archive.dir()));
}

// The machine's name a folder's machine file gives; the folder's when none.
QString machineName(const QString& folder) {
    const Result<usecases::MachineFolderRead> read = usecases::readMachineFolder(folder);
    return read ? read->machine.machine : folder;
}

int runHistory(const QString& dir) {
    const Result<MachineArchive> archive = MachineArchive::open(dir);
    if (!archive) return reportError(archive.error());
    const Result<QList<ArchiveVersion>> versions = archive->versions();
    if (!versions) return reportError(versions.error());
    if (versions->isEmpty()) {
        printOut(QStringLiteral("%1 holds no version yet\n").arg(dir));
        return ExitOk;
    }
    QString text;
    for (const ArchiveVersion& version : *versions) {
        QStringList marks = version.releases;
        if (version.released) marks << QStringLiteral("the released version");
        text += QStringLiteral("%1  %2  %3  %4%5\n")
                    .arg(version.shortId(), timeText(version.time), version.author,
                         version.note.isEmpty() ? QStringLiteral("(no note)") : version.note,
                         marks.isEmpty()
                             ? QString()
                             : QStringLiteral("  [%1]").arg(marks.join(QLatin1String(", "))));
        for (const QString& change : version.changes)
            text += QStringLiteral("    %1\n").arg(change);
        if (version.changes.isEmpty()) text += QStringLiteral("    (no change recorded)\n");
    }
    printOut(text);
    return ExitOk;
}

int runRelease(const QString& dir, const QString& name, const BackupAuthor& author) {
    const Result<MachineArchive> archive = MachineArchive::open(dir);
    if (!archive) return reportError(archive.error());
    const Result<QString> id = archive->resolve(name);
    if (!id) return reportError(id.error());
    const Result<QString> tag = archive->release(*id, author.operatorName, author.note);
    if (!tag) return reportError(tag.error());
    const Result<ArchiveVersion> version = versionOf(*archive, *id);
    if (!version) return reportError(version.error());
    printOut(QStringLiteral("%1: version %2 is the released version of %3 now (%4, by %5)\n")
                 .arg(*tag, versionText(*version), dir, *tag, author.operatorName));
    return ExitOk;
}

// The devices now against the released version: a backup of every device
// into a temporary folder (its lines said only when a device was not
// saved), then the comparison; with `commit` the backup is stored as a new
// version when it differs from the latest one.
int runWatch(const QString& dir, bool commit, const BackupAuthor& author) {
    const Result<MachineArchive> archive = MachineArchive::open(dir);
    if (!archive) return reportError(archive.error());
    const Result<QString> releasedId = archive->released();
    if (!releasedId) return reportError(releasedId.error());
    const Result<ArchiveVersion> released = versionOf(*archive, *releasedId);
    if (!released) return reportError(released.error());
    const Result<usecases::VersionFolder> releasedFolder =
        usecases::takeOutVersion(*archive, *releasedId);
    if (!releasedFolder) return reportError(releasedFolder.error());
    // The devices are reached as the latest version's machine file says.
    const Result<QString> latestId = archive->resolve({});
    if (!latestId) return reportError(latestId.error());
    const Result<usecases::VersionFolder> latest = usecases::takeOutVersion(*archive, *latestId);
    if (!latest) return reportError(latest.error());
    const QString machinePath = QDir(latest->path()).filePath(kMachineBackupFile);
    const Result<QByteArray> bytes = readFileBytes(machinePath);
    if (!bytes) return reportError(bytes.error());
    const Result<MachineSetup> setup = loadMachine(*bytes, machinePath);
    if (!setup) return reportError(setup.error());

    QTemporaryDir now;
    if (!now.isValid())
        return reportError(
            Error::invalidData(QStringLiteral("no temporary folder for the devices' backup: %1")
                                   .arg(now.errorString())));
    MachineRun run;
    run.machinePath = machinePath;  // identities first seen go to the copy, not the archive
    run.dir = now.path();
    run.author = author;
    OutputBlock backupLines;
    int backedUp = ExitOk;
    {
        CaptureOutput capture(backupLines);
        backedUp = runMachineBackup(*setup, run);
    }
    if (backedUp != ExitOk) backupLines.print();

    const Result<usecases::MachineFolderRead> backup = usecases::readMachineFolder(now.path());
    if (!backup) return reportError(backup.error());
    const MachineChanges changes = usecases::compareWithDevicesNow(releasedFolder->path(), *backup);
    printOut(QStringLiteral("%1: the devices now against the released version %2 [%3]\n")
                 .arg(setup->machine.machine, versionText(*released), released->releases.value(0)));
    const int code = printMachineChanges(changes, setup->machine.machine, ExitCommunication);
    if (code == ExitDevice && commit) {
        BackupAuthor by = author;
        if (by.note.isEmpty())
            by.note = QStringLiteral("machine watch: differs from the released version %1")
                          .arg(released->shortId());
        const Result<usecases::VersionStored> stored =
            usecases::storeMachineVersion(*archive, now.path(), by);
        if (!stored) {
            reportError(stored.error());
        } else if (stored->stored) {
            printOut(QStringLiteral("version %1 stored in %2\n").arg(stored->id.left(10), dir));
        } else {
            printOut(QStringLiteral("the latest version %1 holds this state already: no new "
                                    "version stored\n")
                         .arg(latestId->left(10)));
        }
    }
    return code;
}

}  // namespace

int printMachineChanges(const MachineChanges& changes, const QString& machine, int notSavedExit) {
    QString text;
    QStringList summary;
    int worst = ExitOk;
    for (const DeviceChange& device : changes.devices) {
        if (!device.identity.isEmpty())
            text += device.name + QStringLiteral(": ") + device.identity + u'\n';
        for (const BackupDifference& difference : device.differences)
            text += difference.line() + u'\n';
        const QString volatileNote =
            device.volatileLeftOut == 0 ? QString()
                                        : QStringLiteral(" (%1 changes of volatile items left out)")
                                              .arg(device.volatileLeftOut);
        switch (device.kind) {
            case DeviceChange::Kind::Equal:
                summary << QStringLiteral("%1: equal%2").arg(device.name, volatileNote);
                break;
            case DeviceChange::Kind::Changed:
                summary << QStringLiteral("%1: DIFFERS (%2)%3")
                               .arg(device.name)
                               .arg(device.differences.size() + (device.identity.isEmpty() ? 0 : 1))
                               .arg(volatileNote);
                break;
            case DeviceChange::Kind::Added:
            case DeviceChange::Kind::Removed:
                summary << QStringLiteral("%1: DIFFERS: %2")
                               .arg(device.name,
                                    usecases::changeLine(device).mid(device.name.size() + 2));
                break;
            case DeviceChange::Kind::NotSaved:
                summary << QStringLiteral("%1: NOT REACHED: %2").arg(device.name, device.why);
                if (worst != ExitInvalidData) worst = notSavedExit;
                break;
            case DeviceChange::Kind::NotCompared:
                summary << QStringLiteral("%1: NOT COMPARED: %2").arg(device.name, device.why);
                worst = ExitInvalidData;
                break;
        }
    }
    for (const QString& line : changes.machineFile)
        text += QStringLiteral("machine file: %1\n").arg(line);
    printOut(text + QStringLiteral("%1:\n%2\n").arg(machine, summary.join(u'\n')));
    return worst != ExitOk ? worst : changes.changed() ? ExitDevice : ExitOk;
}

bool isMachineArchive(const QString& dir) {
    return QFileInfo(QDir(dir).filePath(QStringLiteral(".git"))).exists() &&
           MachineArchive::open(dir).ok();
}

int runMachineVersionDiff(const QString& dir, const QStringList& versions) {
    const Result<MachineArchive> archive = MachineArchive::open(dir);
    if (!archive) return reportError(archive.error());
    const Result<QString> newer = archive->resolve(versions.value(1));
    if (!newer) return reportError(newer.error());
    const Result<QString> older =
        archive->resolve(versions.isEmpty() ? *newer + QStringLiteral("^") : versions.at(0));
    if (!older)
        return reportError(versions.isEmpty()
                               ? Error::usage(QStringLiteral("%1 holds one version only: nothing "
                                                             "to compare it with")
                                                  .arg(dir))
                               : older.error());
    const Result<ArchiveVersion> olderVersion = versionOf(*archive, *older);
    const Result<ArchiveVersion> newerVersion = versionOf(*archive, *newer);
    if (!olderVersion || !newerVersion)
        return reportError((!olderVersion ? olderVersion : newerVersion).error());
    const Result<usecases::VersionFolder> olderFolder = usecases::takeOutVersion(*archive, *older);
    if (!olderFolder) return reportError(olderFolder.error());
    const Result<usecases::VersionFolder> newerFolder = usecases::takeOutVersion(*archive, *newer);
    if (!newerFolder) return reportError(newerFolder.error());
    printOut(QStringLiteral("version %1\n     → %2\n")
                 .arg(versionText(*olderVersion), versionText(*newerVersion)));
    return printMachineChanges(
        usecases::compareMachineFolders(olderFolder->path(), newerFolder->path()),
        machineName(newerFolder->path()), ExitInvalidData);
}

int runMachineArchiveBackup(const MachineSetup& setup, const MachineRun& run) {
    const Result<MachineArchive> archive = MachineArchive::openOrCreate(run.archive);
    if (!archive) return reportError(archive.error());
    const Result<QList<ArchiveVersion>> versions = archive->versions();
    if (!versions) return reportError(versions.error());
    // The archive's folder is the backup folder: it holds the latest
    // version again whenever no new one is stored.
    MachineRun into = run;
    into.dir = archive->dir();
    const int code = runMachineBackup(setup, into);
    const auto backToLatest = [&]() {
        if (versions->isEmpty()) return;
        if (const Status reset = archive->resetWorkTree(); !reset)
            printError(reset.error().message);
    };
    if (code != ExitOk) {
        backToLatest();
        printOut(QStringLiteral("no version stored in %1: not every device was saved\n")
                     .arg(run.archive));
        return code;
    }
    const Result<usecases::VersionStored> stored =
        usecases::storeMachineVersion(*archive, archive->dir(), run.author);
    if (!stored) {
        backToLatest();
        return reportError(stored.error());
    }
    if (!stored->stored) {
        backToLatest();
        printOut(QStringLiteral("nothing changed since version %1: no new version stored\n")
                     .arg(versionText(versions->first())));
        return ExitOk;
    }
    QString text = QStringLiteral("version %1 stored in %2 by %3\n")
                       .arg(stored->id.left(10), run.archive, run.author.operatorName);
    for (const QString& line : stored->changes.lines())
        text += QStringLiteral("    %1\n").arg(line);
    printOut(text);
    return ExitOk;
}

int runMachineVersionRestore(const QString& dir, const QString& name, const MachineRun& run) {
    const Result<MachineArchive> archive = MachineArchive::open(dir);
    if (!archive) return reportError(archive.error());
    const Result<QString> id = archive->resolve(name);
    if (!id) return reportError(id.error());
    const Result<ArchiveVersion> version = versionOf(*archive, *id);
    if (!version) return reportError(version.error());
    const Result<usecases::VersionFolder> folder = usecases::takeOutVersion(*archive, *id);
    if (!folder) return reportError(folder.error());
    printOut(QStringLiteral("%1 version %2 of %3\n")
                 .arg(run.planOnly ? QStringLiteral("the plan of restoring")
                                   : QStringLiteral("restoring"),
                      versionText(*version), dir));
    MachineRun restore = run;
    // The safety copies go beside the archive, not into the temporary folder.
    restore.safetyBeside = archive->dir();
    return runMachineRestore(folder->path(), restore);
}

int runMachineHistoryVerb(const QString& verb, CommandArgs& args) {
    const Result<QString> dir = args.takeRequiredPositional(QStringLiteral("the machine archive"));
    if (!dir) return reportError(dir.error());
    if (verb == QLatin1String("history")) {
        if (const Status done = args.finish(); !done) return reportError(done.error());
        return runHistory(*dir);
    }
    Result<QString> version = QString();
    if (verb == QLatin1String("release"))
        version = args.takeRequiredPositional(QStringLiteral("the version to release"));
    if (!version) return reportError(version.error());
    const bool commit = verb == QLatin1String("watch") && args.takeFlag(QStringLiteral("--commit"));
    const Result<BackupAuthor> author = takeAuthor(args);
    if (!author) return reportError(author.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    return verb == QLatin1String("release") ? runRelease(*dir, *version, *author)
                                            : runWatch(*dir, commit, *author);
}

}  // namespace cambench::cli
