#pragma once

// Backup, restore and verify of the whole EEPROM, one implementation for the
// GUI's wizard and the CLI.
//
// Restore: the image was checked when loaded (hash, version, blocks); the
// connected device's identity (camConIdentity) is compared with the image's
// (another device is refused unless the person accepted it as the
// replacement of the image's); a safety backup of what the device holds now is
// saved first, named by safetyBackupPath(); then the device is erased and
// written. The report says what state the device is in.

#include "comm/usecases/use_case_progress.h"

#include "comm/camcon/camcon_device.h"
#include "model/camcon/eeprom_image.h"

#include <QDateTime>
#include <QString>
#include <QStringList>

namespace cambench::usecases {

// The one naming of safety backups: "<image>.safety-<UTC yyyyMMddTHHmmssZ>.json"
// in the image's folder, e.g. "line7.json.safety-20261121T231500Z.json":
// it sorts next to the image it was taken before, and says when. Should
// that name exist, "-2", "-3", ... is added before ".json".
QString safetyBackupPath(const QString& imagePath, const QDateTime& utc);

// Reads the whole EEPROM (with the device's identity in image.device).
Result<EepromImage> backupDevice(comm::CamConDevice& connection,
                                 const UseCaseProgress& progress = {});

// What a backup holds besides the blocks.
enum class BackupContent {
    Decoded,    // the content read and decoded too (image.content): a backup a person reads
    ImageOnly,  // the blocks alone: the safety backup just before a restore
};
// Backs up into `path` (atomically); the image is returned as saved.
// Decoded: after the blocks, everything the device holds is read as a
// project (readEverything) into image.content.
Result<EepromImage> backupToFile(comm::CamConDevice& connection, const QString& path,
                                 const UseCaseProgress& progress = {},
                                 BackupContent content = BackupContent::Decoded);

struct RestoreOptions {
    // The person's word that the device answering replaces the one the
    // image was taken from (a restore to another device is refused without).
    ReplacementConsent replacement;
    bool safetyBackup = true;  // false: no safety backup (the user said so)
    QString safetyBackupPath;  // empty: safetyBackupPath(imagePath, now)
};

enum class RestoredState {
    Unchanged,        // refused or failed before anything was erased
    Restored,         // every block written and the device started
    ErasedOrPartial,  // failed during the restore: see the message
};

struct RestoreReport {
    RestoredState state = RestoredState::Unchanged;
    QString safetyBackupPath;      // where the safety backup is; empty when none was taken
    int blocks = 0;                // blocks of the image
    QStringList identityMismatch;  // differences the person accepted (a replacement)
    // Set when the image's communication settings (protocol, device
    // number) are not the device's now: the image puts back its own, and the
    // next connection needs them (empty otherwise).
    QString linkNote;
    Error error;  // kind None when restored; the message says the device's state
    bool ok() const { return state == RestoredState::Restored; }
};

// Runs inside a worker job. `imagePath` names the image in messages and
// places the safety backup. Progress: step 1 safety backup, step 2 restore.
RestoreReport restoreImage(comm::CamConDevice& connection, const EepromImage& image,
                           const QString& imagePath, const RestoreOptions& options = {},
                           const UseCaseProgress& progress = {});

struct VerifyReport {
    bool equal = false;
    int deviceBlocks = 0;
    int imageBlocks = 0;
    QStringList differingBlocks;  // hex block numbers, first ten
    QStringList identityMismatch;
    // "the device equals IMAGE (N blocks)" or what differs.
    QString text(const QString& imagePath) const;
};

// The numbers (4 hex digits) of the blocks where two images differ, the
// first ten.
QStringList differingEepromBlocks(const QList<EepromBlock>& a, const QList<EepromBlock>& b);

// Reads the device's EEPROM and compares it with `image`.
Result<VerifyReport> verifyImage(comm::CamConDevice& connection, const EepromImage& image,
                                 const UseCaseProgress& progress = {});

}  // namespace cambench::usecases
