#pragma once

// A machine's devices backed up, verified and restored one by one, each in
// one worker job on its own connection (issue 36): first who answers -
// another device than the one recorded is said and nothing is saved from
// it, verified or written to it unless the person accepted it as the
// replacement - then its family's FamilyBackup. The machine commands run
// these on one thread per port (app/cli/machine_*.cpp), the machine window
// on each device's worker. Names no family; nothing here prints.

#include "comm/usecases/family_backup.h"
#include "model/machine/machine_backup_folder.h"
#include "model/machine/machine_file.h"

#include <QString>

#include <optional>

namespace cambench::comm {
class DeviceConnection;
class JobContext;
}  // namespace cambench::comm

namespace cambench::usecases {

// Who a device is: what it says of itself for a person (identify()) and
// its identity to compare (readIdentity()). Queries only.
struct DeviceAnswer {
    QString text;
    DeviceIdentity identity;
};
Result<DeviceAnswer> whoAnswers(comm::DeviceConnection& connection);

// What asking a device before the work found. `another` ("another device
// answers: expected ..., found ...") when `expected` is known, the device
// that answered is another one and the person did not accept it: the
// work was not done.
struct DeviceChecked {
    DeviceAnswer found;
    QString another;
};

// One device's backup into `dir` (its file: deviceFileName()). The entry
// is the manifest's: "saved", or "failed: why" (not reached, another
// device, the family has no backup, the device refused an item); `error`
// says why for a person.
struct DeviceBackedUp {
    ManifestEntry entry;
    std::optional<DeviceChecked> checked;  // when the device was reached
    Error error;                           // kind None when saved
};
DeviceBackedUp backUpMachineDevice(comm::JobContext& job, const MachineDevice& device,
                                   const QString& dir, bool replacement);

// A device's file of the backup folder `dir` (the manifest's `entry`)
// against the device: its identity first (`accepted`: the person's word
// for another one: the command line's --replacement accepts any, the
// GUI's question the identity it showed), then the family's verify. An error when not reached
// or the work failed; `checked.another` when another device answered.
struct DeviceVerified {
    DeviceChecked checked;
    BackupComparison comparison;
};
Result<DeviceVerified> verifyMachineDevice(comm::JobContext& job, const ManifestEntry& entry,
                                           const QString& dir, const ReplacementConsent& consent);

// The plan of a device's restore from `dir` (nothing written), and the
// restore itself; `request.replacement` carries the person's word.
struct DevicePlanned {
    DeviceChecked checked;
    RestorePlan plan;
};
Result<DevicePlanned> planMachineDevice(comm::JobContext& job, const ManifestEntry& entry,
                                        const QString& dir, const RestoreRequest& request);
struct DeviceRestored {
    DeviceChecked checked;
    RestoreResult result;
};
Result<DeviceRestored> restoreMachineDevice(comm::JobContext& job, const ManifestEntry& entry,
                                            const QString& dir, const RestoreRequest& request);

// Two backup folders' files of one device (a machine diff), no device.
Result<BackupComparison> diffMachineDevice(const ManifestEntry& first, const QString& firstDir,
                                           const ManifestEntry& second, const QString& secondDir);

}  // namespace cambench::usecases
