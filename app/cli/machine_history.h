#pragma once

// The machine's history on the command line (issue 37): `machine backup
// M.json --archive DIR -m WHY`, `machine history DIR`, `machine diff DIR
// [A [B]]`, `machine restore DIR --version A`, `machine release DIR
// VERSION`, `machine watch DIR [--commit]`. The backup and the restore are
// the machine's own (machine_backup.cpp); what changed is the use case's
// (comm/usecases/machine_history.h). Names no family.

#include "cli_options.h"
#include "machine_command.h"

#include "comm/usecases/machine_history.h"

#include <QString>
#include <QStringList>

namespace cambench::cli {

// Every difference a line ("cams: program 3, output 2: cam 100–200
// added"), then a line per device; the exit code: 4 when a device could not
// be compared, `notSavedExit` when one was not saved (3 for the devices now:
// not reached; 4 for a folder that lacks it), 1 when one differs. `machine
// diff` of two folders or two versions and `machine watch` print so.
int printMachineChanges(const usecases::MachineChanges& changes, const QString& machine,
                        int notSavedExit);

// Whether `dir` is the top folder of a git repository (an archive).
bool isMachineArchive(const QString& dir);

// `machine history|release|watch ...`: the verb taken, the rest in `args`.
int runMachineHistoryVerb(const QString& verb, CommandArgs& args);

// `machine diff ARCHIVE [A [B]]`: B (default the latest) against A
// (default the version before B) - exit 0 equal, 1 differ.
int runMachineVersionDiff(const QString& dir, const QStringList& versions);

// `machine backup M.json --archive DIR`: the backup into the archive's
// folder, then a new version when something changed.
int runMachineArchiveBackup(const MachineSetup& setup, const MachineRun& run);

// `machine restore DIR --version A`: the machine restore of that version.
int runMachineVersionRestore(const QString& dir, const QString& version, const MachineRun& run);

}  // namespace cambench::cli
