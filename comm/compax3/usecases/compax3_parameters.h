#pragma once

// Parameter sets of a Compax3: read a list of objects into a file, compare
// a file with the drive, write a file back (the "replace a broken drive at
// 2 a.m." workflow). One implementation for the GUI and the CLI, run inside
// a worker job.

#include "comm/compax3/compax3_device.h"
#include "comm/usecases/item_outcome.h"
#include "comm/usecases/use_case_progress.h"
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
    Compax3ParameterSet set;
    // Objects not in the set because the drive refused them: a backup with
    // refusals is incomplete, and says so.
    QList<Compax3Refusal> refused;
};

// Reads the drive's identity and every object of `objects` (in that order),
// each until two answers in a row agree (the protocol has no checksum). A
// line failure ends it with an error; a refused object is listed.
Result<Compax3Backup> takeCompax3Parameters(comm::Compax3Device& device,
                                            const QList<Compax3ObjectId>& objects,
                                            const UseCaseProgress& progress = {});

// One object whose value on the drive is not the file's.
struct Compax3Difference {
    Compax3ObjectId id;
    QString fileValue;
    QString driveValue;  // empty with `error`
    QString error;       // the drive refused to read it
};

struct Compax3Comparison {
    Compax3Identity drive;
    int compared = 0;
    QList<Compax3Difference> differences;
    // "1901.1 (Set 1 target): file 100, drive 250".
    static QString lineFor(const Compax3Difference& difference,
                           const Compax3Dictionary& dictionary);
};

// Reads every object of the file from the drive and lists the differences.
Result<Compax3Comparison> compareCompax3Parameters(comm::Compax3Device& device,
                                                   const Compax3ParameterSet& set,
                                                   const UseCaseProgress& progress = {});

// One object to write: its value as a person or a file gave it and as it
// goes on the wire (compax3WireValueFor made it: checked already).
struct Compax3Write {
    Compax3ObjectId id;
    QString value;
    QString wire;
};

// Writes each object that differs on the drive, reads it back and reports
// it written, unchanged or failed (what reading back found); after a line
// failure the rest is "not sent". The Objects page's "Write changes" and
// restoreCompax3Parameters both end here.
OutcomeTally writeCompax3Objects(comm::Compax3Device& device, const QList<Compax3Write>& writes,
                                 const Compax3Dictionary& dictionary,
                                 const UseCaseProgress& progress = {});

struct Compax3RestoreOptions {
    bool force = false;  // a set of another drive type
    // Only these objects (empty: every differing one of the file).
    QList<Compax3ObjectId> only;
    // Afterwards, stores the sets in the drive's flash (1904.1 = $32).
    bool store = false;
};

// Checks before the first byte: the drive's type (refused unless forced),
// every value against the dictionary (range, type, read-only). Then writes
// what differs, reads each object back and reports it written, unchanged
// or failed; after a line failure the rest is "not sent".
Result<OutcomeTally> restoreCompax3Parameters(comm::Compax3Device& device,
                                              const Compax3ParameterSet& set,
                                              const Compax3Dictionary& dictionary,
                                              const Compax3RestoreOptions& options,
                                              const UseCaseProgress& progress = {});

}  // namespace cambench::usecases
