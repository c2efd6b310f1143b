#pragma once

// A machine's history (issue 37) on its archive (model/machine/
// machine_archive.h): what changed between two states of the machine -
// two versions, or the released version and the devices now - device by
// device in each family's own terms (its FamilyBackup's diff, through
// diffMachineDevice), with the items the machine file names as volatile
// left out; the one line per changed device that a version's message and
// `machine history` carry; and a backup folder stored as a new version only
// when something changed. The machine commands (app/cli/machine_history.cpp)
// and the history dialog (ui/machine/machine_history_dialog.h) call these.
// Names no family; nothing here prints.

#include "comm/usecases/family_backup.h"
#include "model/backup_difference.h"
#include "model/machine/machine_archive.h"
#include "model/machine/machine_backup_folder.h"
#include "model/machine/machine_file.h"

#include <QList>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>

#include <memory>

namespace cambench::usecases {

// A machine backup folder read: its machine file and its manifest.
struct MachineFolderRead {
    QString dir;
    MachineFile machine;
    MachineManifest manifest;
};
Result<MachineFolderRead> readMachineFolder(const QString& dir);

// What became of one device between an older and a newer state.
struct DeviceChange {
    enum class Kind {
        Equal,
        Changed,
        Added,        // only in the newer state
        Removed,      // only in the older state
        NotSaved,     // a state lacks its backup (not reached, another device, ...)
        NotCompared,  // its files could not be compared (`why` says why)
    };
    QString name;
    Kind kind = Kind::Equal;
    // The differences, the volatile ones left out; old = the older state.
    QList<BackupDifference> differences;
    int volatileLeftOut = 0;  // differences of volatile items not counted
    // Another device in the newer state: "serial C3-1001 → C3-1002".
    QString identity;
    // Added: what its backup holds (the manifest's summary); NotSaved,
    // NotCompared: why.
    QString why;
};

struct MachineChanges {
    QList<DeviceChange> devices;  // the newer machine file's order, then the removed ones
    // The machine file's own changes beside the devices' contents, one
    // line each ("feed: port /dev/ttyUSB1 → /dev/ttyUSB2").
    QStringList machineFile;

    bool changed() const;   // a device or the machine file changed
    bool complete() const;  // every device compared
    // One line per changed device and one for the machine file: a
    // version's message and `machine history` ("cams: program 3: output
    // 2, output 7", "feed: 1902.1 Set 1 velocity 200 → 350").
    QStringList lines() const;
};

// The one line of a device that changed (empty when it did not): its only
// difference whole; several named by their items, with the part they
// share said once ("program 3: output 2, output 7"), at most eight, then
// "and N more".
QString changeLine(const DeviceChange& change);

// The differences of `comparison` whose item `items` (a device's
// "volatile" list) does not name; how many were left out in `leftOut`.
QList<BackupDifference> withoutVolatile(const QList<BackupDifference>& differences,
                                        const QStringList& items, int* leftOut);

// Two backup folders of the machine, no device asked (the older first).
// The volatile items of either machine file are left out.
MachineChanges compareMachineFolders(const QString& older, const QString& newer);

// The devices now - a backup of each just taken into `now.dir`, its
// manifest and the machine file in `now` (`machine watch`, History →
// Compare with the devices now, the machine report's changes since the
// released version) - against the version taken out into `version`, as
// compareMachineFolders compares them. Where a device is reached (the
// machine file's options) is no difference of the device; one whose
// backup now failed says why in its manifest's words, not as a folder
// that was temporary.
MachineChanges compareWithDevicesNow(const QString& version, const MachineFolderRead& now);

// The first state of a machine (no version before it): every saved device
// "first version" with its summary.
MachineChanges firstVersionOf(const QString& folder);

// A version of `archive` taken out into a temporary folder, removed when
// the object goes.
struct VersionFolder {
    QString id;
    std::unique_ptr<QTemporaryDir> folder;
    QString path() const { return folder->path(); }
};
Result<VersionFolder> takeOutVersion(const MachineArchive& archive, const QString& id);

// The backup folder `staged` (a complete machine backup: every device
// saved) stored in `archive` as a new version whose author is
// `author.operatorName` and whose message is `author.note` and the
// changes, when it differs from the latest version; else nothing is
// stored. A folder with a device not saved is refused: a version lacking
// a device would read as the device taken out.
struct VersionStored {
    bool stored = false;
    QString id;  // the new version's; empty when nothing was stored
    MachineChanges changes;
};
Result<VersionStored> storeMachineVersion(const MachineArchive& archive, const QString& staged,
                                          const BackupAuthor& author);

}  // namespace cambench::usecases
