#pragma once

#include "cli_options.h"
#include "cli_session.h"

#include "model/machine/machine_backup_folder.h"
#include "model/machine/machine_file.h"

#include <QByteArray>
#include <QList>
#include <QString>
#include <QStringList>

namespace cambench::cli {

// A machine file with every device's options parsed as the command line
// parses them: nothing is asked of a device before all of them fit.
struct MachineSetup {
    MachineFile machine;
    QList<GlobalOptions> options;  // one per device, in the file's order
};

// `where` names the file in messages. A device whose options do not fit
// (a wrong family, a protocol of another family) is refused naming it.
Result<MachineSetup> loadMachine(const QByteArray& bytes, const QString& where);
// The same of a machine file already read.
Result<MachineSetup> machineSetup(const MachineFile& machine, const QString& where);

// The devices `names` (--replacement a,b) are: refused naming the one the
// machine lacks.
Status checkDeviceNames(const MachineFile& machine, const QStringList& names,
                        const QString& option);

// What a machine backup or restore was asked for on the command line.
struct MachineRun {
    QString machinePath;  // backup: the person's machine file (identities recorded there)
    QString dir;          // backup: the folder to fill
    bool resume = false;  // backup: keep the devices an earlier run saved
    // The devices the person accepts in place of the ones recorded
    // (machine backup records their new identity; machine restore writes
    // their backup into them).
    QStringList replacements;
    QStringList only;       // restore: these devices only
    bool planOnly = false;  // restore --plan: say what would be written, write nothing
    BackupAuthor author;    // who, why, with what (--operator, -m, this build)
    QString archive;        // backup --archive: the machine's archive (issue 37)
    // restore: the folder the safety copies go beside (empty: the backup
    // folder; a version of an archive is restored from a temporary folder).
    QString safetyBeside;
};

// --operator NAME and -m WHY (the login name when no operator is named),
// with this build's version and revision.
Result<BackupAuthor> takeAuthor(CommandArgs& args);

// machine status / backup / verify / restore / diff; each returns the
// exit code.
int runMachineStatus(const MachineSetup& setup, bool json);
int runMachineBackup(const MachineSetup& setup, const MachineRun& run);
int runMachineVerify(const QString& dir, const QStringList& replacements);
int runMachineRestore(const QString& dir, const MachineRun& run);
// Two backup folders of the machine, device by device, no device asked:
// exit 0 equal, 1 differ.
int runMachineDiff(const QString& first, const QString& second);

}  // namespace cambench::cli
