#pragma once

// Parameter sets of a Compax3: read a list of objects into a file, compare
// a file with the drive, write a file back (the "replace a broken drive at
// 2 a.m." workflow). One implementation for the GUI and the CLI, run inside
// a worker job.

#include "comm/compax3/compax3_device.h"
#include "comm/usecases/item_outcome.h"
#include "comm/usecases/use_case_progress.h"
#include "model/backup_difference.h"
#include "model/compax3/compax3_dictionary.h"
#include "model/compax3/compax3_parameter_file.h"

#include <QList>
#include <QStringList>

namespace cambench::usecases {

// An object the drive refused to read, with the drive's words.
struct Compax3Refusal {
    Compax3ObjectId id;
    QString reason;  // "the drive refused O1901,40 with !0002 (no such object)"
};

struct Compax3Backup {
    // Objects the drive does not have are in `set.absent`: the backup is
    // complete without them and names them.
    Compax3ParameterSet set;
    // Objects not in the set because the drive refused them otherwise: a
    // backup with refusals is incomplete, and says so.
    QList<Compax3Refusal> refused;
    // Control words and functions that were asked for: never read into a
    // file (compax3NeverFromAFile says why).
    QList<Compax3Refusal> notSaved;
};

// Reads the drive's identity and every object of `objects` (in that order),
// each until two answers in a row agree (the protocol has no checksum). A
// line failure ends it with an error; an object the drive does not have is
// recorded absent; another refusal is listed.
Result<Compax3Backup> takeCompax3Parameters(comm::Compax3Device& device,
                                            const QList<Compax3ObjectId>& objects,
                                            const Compax3Dictionary& dictionary,
                                            const UseCaseProgress& progress = {});

// One object whose value on the drive is not the file's.
struct Compax3Difference {
    Compax3ObjectId id;
    QString fileValue;   // empty with `absentInFile`
    QString driveValue;  // empty with `error`
    QString error;       // the drive refused to read it ("not on this drive")
    // The file records the object as not on the drive it was read from, and
    // this drive has it.
    bool absentInFile = false;
};

struct Compax3Comparison {
    Compax3Identity drive;
    int compared = 0;
    // Objects absent in the file and on this drive: equal, counted here.
    int absentOnBoth = 0;
    QList<Compax3Difference> differences;
    // Control words and functions in the file: not compared, never taken
    // from a file.
    QList<Compax3Refusal> ignored;
    // "1901.1 (Set 1 target): file 100, drive 250".
    static QString lineFor(const Compax3Difference& difference,
                           const Compax3Dictionary& dictionary);
};

// An object's name as the set records it, else the dictionary's; empty
// when neither knows it.
QString nameOf(const Compax3ParameterSet& set, const Compax3Dictionary& dictionary,
               const Compax3ObjectId& id);
// The object's name in `dictionary`, or empty.
QString nameIn(const Compax3Dictionary& dictionary, const Compax3ObjectId& id);

// One difference as the machine says it: "1902.1 Set 1 velocity 200 →
// 321" (old = fileValue, new = driveValue).
BackupDifference compax3ObjectDifference(const Compax3Difference& difference, const QString& name);
// Every difference of a comparison (old = the file's, new = the drive's).
QList<BackupDifference> compax3ComparisonItems(const Compax3Comparison& comparison,
                                               const Compax3ParameterSet& set,
                                               const Compax3Dictionary& dictionary);
// Two parameter sets, no drive: old = `before`, new = `after`; the drive
// itself (type, serial number) too.
QList<BackupDifference> diffCompax3Sets(const Compax3ParameterSet& before,
                                        const Compax3ParameterSet& after,
                                        const Compax3Dictionary& dictionary);

// Reads every object of the file (and those it records absent) from the
// drive and lists the differences.
Result<Compax3Comparison> compareCompax3Parameters(comm::Compax3Device& device,
                                                   const Compax3ParameterSet& set,
                                                   const Compax3Dictionary& dictionary,
                                                   const UseCaseProgress& progress = {});

// One object to write: its value as a person or a file gave it and as it
// goes on the wire (compax3WireValueFor made it: checked already).
struct Compax3Write {
    Compax3ObjectId id;
    QString value;
    QString wire;
};

// Where the values of a write come from: what a person typed on the
// Objects page, or a file (a restore, a compare's "write the file's value").
enum class Compax3WriteSource { Typed, File };

// Writes each object that differs on the drive, reads it back and reports
// it written, unchanged or failed (what reading back found); after a line
// failure the rest is "not sent". The Objects page's "Write changes" and
// restoreCompax3Parameters both end here: the one write path. It sends
// nothing to a control word (compax3IsControlWord) and, from a file,
// nothing to a function (compax3NeverFromAFile), whatever the dictionary
// says; those are "not sent" with the reason.
OutcomeTally writeCompax3Objects(comm::Compax3Device& device, const QList<Compax3Write>& writes,
                                 const Compax3Dictionary& dictionary, Compax3WriteSource source,
                                 const UseCaseProgress& progress = {});

struct Compax3RestoreOptions {
    // The person's word that the drive answering replaces the one the set
    // was read from (serial number or type differ).
    ReplacementConsent replacement;
    bool force = false;  // a set of another drive type
    // Only these objects (empty: every differing one of the file).
    QList<Compax3ObjectId> only;
    // Afterwards, stores each set an object was written into in the drive's
    // flash (1904.n = $32).
    bool store = false;
};

// What restoreCompax3Parameters would write, after the same checks (an
// error: nothing would be written, and nothing was): old = the drive's
// value now, new = the file's ("1902.1 Set 1 velocity 321 → 200").
Result<QList<BackupDifference>> planCompax3Restore(comm::Compax3Device& device,
                                                   const Compax3ParameterSet& set,
                                                   const Compax3Dictionary& dictionary,
                                                   const Compax3RestoreOptions& options,
                                                   const UseCaseProgress& progress = {});

// Checks before the first byte: the drive's identity (serial number and
// type: another drive is refused unless accepted as the replacement), its
// type (another type's set is refused unless forced),
// every value against the dictionary (range, type, read-only). Then writes
// what differs, reads each object back and reports it written, unchanged
// or failed; after a line failure the rest is "not sent".
Result<OutcomeTally> restoreCompax3Parameters(comm::Compax3Device& device,
                                              const Compax3ParameterSet& set,
                                              const Compax3Dictionary& dictionary,
                                              const Compax3RestoreOptions& options,
                                              const UseCaseProgress& progress = {});

}  // namespace cambench::usecases
