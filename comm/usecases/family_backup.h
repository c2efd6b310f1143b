#pragma once

// Backup, verify, diff and restore of one device as typed parts of its
// family (issue 36, item 1): each family registers a FamilyBackup (through
// its FamilyParts::backup, app/registry/<family>/); the single-device
// commands, the machine commands and the machine window call the same
// one. Results are data - a file, an identity, differences item by item,
// a plan, an outcome per item - and nothing here prints: the CLI and the
// GUI word them.

#include "comm/usecases/item_outcome.h"
#include "model/backup_difference.h"
#include "model/device_identity.h"
#include "model/result.h"

#include <QHash>
#include <QList>
#include <QString>
#include <QStringList>

#include <memory>

namespace cambench::comm {
class JobContext;
}

namespace cambench::usecases {

// What a backup saved.
struct BackupTaken {
    QString path;
    DeviceIdentity identity;  // of the device it was taken from
    QString device;           // what the device said of itself (identify())
    // "1024 EEPROM blocks, 16 programs, 48 outputs", "1000 variables and
    // 2048 flags of the MC200", "212 objects of Compax3 S150V4 (serial ...)".
    QString summary;
    // Items the device refused or the file lacks, one sentence each: the
    // file is saved, but not complete.
    QStringList incomplete;
    bool complete() const { return incomplete.isEmpty(); }
};

// A backup compared with the device (verify) or with another backup (diff).
struct BackupComparison {
    int compared = 0;  // items compared, in the family's units
    QList<BackupDifference> differences;
    // What was not compared and why, one sentence each (a Compax3's
    // control words in the file).
    QStringList notes;
    bool equal() const { return differences.isEmpty(); }
};

struct RestoreRequest {
    // The person's word that the device answering replaces the one the
    // backup was taken from.
    ReplacementConsent replacement;
    // A Compax3 set of another drive type (checked values still).
    bool force = false;
    // Where the safety copy of what the device holds goes, for a family
    // that takes one before it erases (the CamCon); empty: beside the
    // backup file, named by the family. A machine restore puts it beside
    // the backup folder.
    QString safetyCopy;
};

// What a restore will write, read from the device before anything is sent.
struct RestorePlan {
    // What will change on the device: old = what it holds now, new = the
    // backup's.
    QList<BackupDifference> changes;
    // How it is written, one sentence each: "the whole EEPROM is erased
    // and written again (1024 blocks) after a safety copy", "only the
    // differing items are written, each read back".
    QStringList steps;
};

struct RestoreResult {
    OutcomeTally outcomes;  // one line per item written, unchanged, failed or not sent
    QString safetyCopy;     // where the safety copy went; empty when none was taken
    bool ok() const { return outcomes.complete(); }
};

// A family's backup part. Every device call runs inside a worker job on a
// connection of the family (JobContext::family<...>; another family is a
// Usage error). `path` is the device's backup file.
class FamilyBackup {
public:
    virtual ~FamilyBackup() = default;

    // Reads the device and saves its backup to `path` (atomically).
    virtual Result<BackupTaken> backup(comm::JobContext& job, const QString& path) const = 0;
    // The identity the file records (not known in a file older than that
    // record); the file is checked (hash, format) as a restore would.
    virtual Result<DeviceIdentity> fileIdentity(const QString& path) const = 0;
    // The file against the device: old = the file's, new = the device's.
    virtual Result<BackupComparison> verify(comm::JobContext& job, const QString& path) const = 0;
    // Two files of the family, no device: old = `first`, new = `second`.
    virtual Result<BackupComparison> diff(const QString& first, const QString& second) const = 0;
    // What restore() would write, read from the device; nothing is written.
    // Refused (nothing written) as restore() refuses: another device
    // without consent, a file that does not fit.
    virtual Result<RestorePlan> plan(comm::JobContext& job, const QString& path,
                                     const RestoreRequest& request) const = 0;
    // Checks the file and the device's identity before the first byte,
    // then writes; an error means nothing was written.
    virtual Result<RestoreResult> restore(comm::JobContext& job, const QString& path,
                                          const RestoreRequest& request) const = 0;
};

// The families' backup parts, registered once at start (FamilyParts::backup).
class BackupRegistry {
public:
    static BackupRegistry& instance();
    void add(const QString& familyId, std::shared_ptr<const FamilyBackup> part);
    // Null for a family without one.
    const FamilyBackup* find(const QString& familyId) const;

private:
    QHash<QString, std::shared_ptr<const FamilyBackup>> m_parts;
};

}  // namespace cambench::usecases
