#pragma once

// Backup, verify and restore of an MC100/MC200's variables, external flags
// and memory ranges: one implementation for the GUI and the CLI, run
// inside a worker job.
//
// Restore checks the file against the connected controller before the
// first byte (its identity: the controller the file was taken from or its
// accepted replacement; MC100 or MC200, the flags' page, memory writable),
// reads what
// the controller holds, writes only the differences and reports every item
// as written, unchanged or failed with what was read back.

#include "comm/mc1/mc1_device.h"
#include "comm/usecases/item_outcome.h"
#include "comm/usecases/use_case_progress.h"
#include "model/mc1/mc1_backup_file.h"

#include <QList>
#include <QStringList>

namespace cambench::usecases {

// What a backup takes: variables first..last (none when first > last), the
// external flag page, memory ranges (address, length).
struct Mc1BackupScope {
    int firstVariable = 1;
    int lastVariable = 1000;
    bool flags = true;
    QList<std::pair<int, int>> memory;
};
// The default scope: every variable of the controller and its flags.
Mc1BackupScope defaultMc1BackupScope(comm::Mc1Variant variant);

// With the controller's identity (Mc1Device::readIdentity) in the backup.
Result<Mc1Backup> takeMc1Backup(comm::Mc1Device& device, const Mc1BackupScope& scope,
                                const UseCaseProgress& progress = {});

struct Mc1VerifyReport {
    int compared = 0;         // variables + flags + memory bytes compared
    QStringList differences;  // "V12: file -5, controller 7"
};
// Reads what the file holds from the controller and lists the differences.
Result<Mc1VerifyReport> verifyMc1Backup(comm::Mc1Device& device, const Mc1Backup& backup,
                                        const UseCaseProgress& progress = {});

// An error (nothing written) when the file does not fit the controller or
// another controller answers than the one it was taken from (unless
// `replacement` accepts it; a file that records no identity is refused the
// same way); otherwise one line per variable, differing flag and memory
// chunk.
Result<OutcomeTally> restoreMc1Backup(comm::Mc1Device& device, const Mc1Backup& backup,
                                      const ReplacementConsent& replacement = {},
                                      const UseCaseProgress& progress = {});

}  // namespace cambench::usecases
