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
#include "model/backup_difference.h"
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

// What differs between two states of a controller, item by item: old =
// `before`, new = `after` ("V12 0 → 4711", "M7 1 → 0", "memory
// 0x1000–0x10FF: 3 bytes differ, the first at 0x1004"); variables, flags
// and memory ranges only one side holds are added or removed.
QList<BackupDifference> diffMc1Backups(const Mc1Backup& before, const Mc1Backup& after);
// "memory 0x1000–0x10FF": a range in the words of every MC-1 report.
QString mc1MemoryLabel(int address, int length);
// Variables + flags + memory bytes: the items a comparison of it counts.
int mc1ItemCount(const Mc1Backup& backup);

struct Mc1VerifyReport {
    int compared = 0;  // variables + flags + memory bytes compared
    // Old = the file's, new = the controller's.
    QList<BackupDifference> items;
    QStringList differences;  // their lines: "V12 -5 → 7"
};
// Reads what the file holds from the controller and lists the differences.
Result<Mc1VerifyReport> verifyMc1Backup(comm::Mc1Device& device, const Mc1Backup& backup,
                                        const UseCaseProgress& progress = {});

// What a restore of `backup` would write: old = what the controller holds
// now, new = the file's. Refused as restoreMc1Backup refuses; nothing is
// written.
Result<QList<BackupDifference>> planMc1Restore(comm::Mc1Device& device, const Mc1Backup& backup,
                                               const ReplacementConsent& replacement = {},
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
