#include "compax3_parameters.h"

#include "comm/compax3/compax3_syntax.h"

#include <QCoreApplication>
#include <QSet>

#include <algorithm>

namespace cambench::usecases {

using comm::Compax3Device;

namespace {

bool stopsTheWork(const Error& error) {
    return error.kind == ErrorKind::Communication || error.kind == ErrorKind::Cancelled;
}

// The ASCII protocol has no checksum: a digit damaged on the line reads as
// another number. A value that goes into a file, or that decides whether
// an object differs, is read until two answers in a row agree.
constexpr int kMostReads = 4;

Result<QString> readAgreed(Compax3Device& device, const Compax3ObjectId& id,
                           std::optional<QString> first = std::nullopt) {
    QString previous;
    if (first) {
        previous = *first;
    } else {
        const Result<QString> value = device.readObject(id, false);
        if (!value) return value;
        previous = *value;
    }
    for (int read = 1; read < kMostReads; ++read) {
        const Result<QString> again = device.readObject(id, false);
        if (!again) return again;
        if (*again == previous) return previous;
        previous = *again;
    }
    return Error::communication(
        QCoreApplication::translate("cambench::usecases",
                                    "%1 read %2 times, no two answers in a row agreed: the line "
                                    "damages answers (check the cable, its shield and the baud "
                                    "rate)")
            .arg(id.text())
            .arg(kMostReads));
}

// Reads `id`; when it seems to differ from `expected`, reads it until two
// answers agree, so that a damaged answer does not pass for a difference.
Result<QString> readConfirmed(Compax3Device& device, const Compax3ObjectId& id,
                              const QString& expected) {
    const Result<QString> value = device.readObject(id, false);
    if (!value || compax3SameValue(*value, expected)) return value;
    return readAgreed(device, id, *value);
}

QString label(const Compax3ObjectId& id, const Compax3Dictionary& dictionary) {
    const Compax3ObjectInfo* info = dictionary.find(id);
    return info ? QStringLiteral("%1 (%2)").arg(id.text(), info->name) : id.text();
}

}  // namespace

Result<Compax3Backup> takeCompax3Parameters(Compax3Device& device,
                                            const QList<Compax3ObjectId>& objects,
                                            const Compax3Dictionary& dictionary,
                                            const UseCaseProgress& progress) {
    Compax3Backup backup;
    const Result<Compax3Identity> identity = device.identity();
    if (!identity) return identity.error();
    backup.set.drive = *identity;
    backup.set.taken = QDateTime::currentDateTimeUtc();
    backup.set.toolVersion = QCoreApplication::applicationVersion();
    for (int i = 0; i < objects.size(); ++i) {
        if (progress.cancelled()) return Error::cancelled();
        const Compax3ObjectId& id = objects.at(i);
        if (const QString never = compax3NeverFromAFile(dictionary, id); !never.isEmpty()) {
            backup.notSaved << Compax3Refusal{id, never};
            continue;
        }
        const Result<QString> value = readAgreed(device, id);
        if (value)
            backup.set.values << Compax3ParameterValue{id, *value, nameIn(dictionary, id)};
        else if (comm::compax3RefusalMeansAbsent(value.error(), device.dictionary().refusals()))
            backup.set.absent << id;
        else if (value.error().kind == ErrorKind::DeviceError)
            backup.refused << Compax3Refusal{id, value.error().message};
        else
            return value.error();
        progress.report(i + 1, objects.size(),
                        QCoreApplication::translate("cambench::usecases", "Reading objects"));
    }
    return backup;
}

QString Compax3Comparison::lineFor(const Compax3Difference& difference,
                                   const Compax3Dictionary& dictionary) {
    const QString what = label(difference.id, dictionary);
    if (difference.absentInFile)
        return QCoreApplication::translate(
                   "cambench::usecases",
                   "%1: file: not on the drive it was read from, drive %2 (left as it is)")
            .arg(what, difference.driveValue);
    if (!difference.error.isEmpty())
        return QCoreApplication::translate("cambench::usecases", "%1: file %2, drive: %3")
            .arg(what, difference.fileValue, difference.error);
    return QCoreApplication::translate("cambench::usecases", "%1: file %2, drive %3")
        .arg(what, difference.fileValue, difference.driveValue);
}

namespace {

QString notOnThisDrive() {
    return QCoreApplication::translate("cambench::usecases", "not on this drive");
}

}  // namespace

Result<Compax3Comparison> compareCompax3Parameters(Compax3Device& device,
                                                   const Compax3ParameterSet& set,
                                                   const Compax3Dictionary& dictionary,
                                                   const UseCaseProgress& progress) {
    Compax3Comparison comparison;
    const Result<Compax3Identity> identity = device.identity();
    if (!identity) return identity.error();
    comparison.drive = *identity;
    const qsizetype total = set.values.size() + set.absent.size();
    for (int i = 0; i < set.values.size(); ++i) {
        if (progress.cancelled()) return Error::cancelled();
        const Compax3ParameterValue& wanted = set.values.at(i);
        if (const QString never = compax3NeverFromAFile(dictionary, wanted.id); !never.isEmpty()) {
            comparison.ignored << Compax3Refusal{wanted.id, never};
            continue;
        }
        const Result<QString> value = readConfirmed(device, wanted.id, wanted.value);
        if (!value && value.error().kind != ErrorKind::DeviceError) return value.error();
        ++comparison.compared;
        if (!value)
            comparison.differences << Compax3Difference{
                wanted.id,
                wanted.value,
                {},
                comm::compax3RefusalMeansAbsent(value.error(), device.dictionary().refusals())
                    ? notOnThisDrive()
                    : value.error().message};
        else if (!compax3SameValue(*value, wanted.value))
            comparison.differences << Compax3Difference{wanted.id, wanted.value, *value, {}};
        progress.report(i + 1, total,
                        QCoreApplication::translate("cambench::usecases", "Comparing objects"));
    }
    // Absent on the file's drive: equal when absent here too.
    for (int i = 0; i < set.absent.size(); ++i) {
        if (progress.cancelled()) return Error::cancelled();
        const Compax3ObjectId& id = set.absent.at(i);
        const Result<QString> value = device.readObject(id, false);
        if (!value &&
            !comm::compax3RefusalMeansAbsent(value.error(), device.dictionary().refusals())) {
            if (value.error().kind != ErrorKind::DeviceError) return value.error();
            comparison.differences << Compax3Difference{id, {}, {}, value.error().message, true};
        } else if (value) {
            comparison.differences << Compax3Difference{id, {}, *value, {}, true};
        } else {
            ++comparison.absentOnBoth;
        }
        ++comparison.compared;
        progress.report(set.values.size() + i + 1, total,
                        QCoreApplication::translate("cambench::usecases", "Comparing objects"));
    }
    return comparison;
}

namespace {

// A line for an object nothing was sent to, with the reason.
OutcomeLine notSentLine(const QString& what, const Error& why) {
    return OutcomeLine{what, WriteState::NotSent,
                       outcomeText(what, WriteState::NotSent, {}, why, {}), why};
}

// Why nothing may be sent to `id` from `source`, or empty.
QString refusedFrom(Compax3WriteSource source, const Compax3Dictionary& dictionary,
                    const Compax3ObjectId& id) {
    if (source == Compax3WriteSource::File) return compax3NeverFromAFile(dictionary, id);
    if (compax3IsControlWord(dictionary, id)) return compax3NeverFromAFile(dictionary, id);
    return {};
}

// Everything that can be known without the drive's values: the type, each
// value, the selection. An error here means nothing was written.
Result<QList<Compax3Write>> checkRestore(const Compax3Identity& drive,
                                         const Compax3ParameterSet& set,
                                         const Compax3Dictionary& dictionary,
                                         const Compax3RestoreOptions& options) {
    if (!options.force && drive.type() != set.drive.type())
        return Error::invalidData(
            QCoreApplication::translate(
                "cambench::usecases",
                "the file is from a drive of type %1 (\"%2\"), the connected drive is of type %3 "
                "(\"%4\"): nothing was written. Restore it with --force (GUI: \"Write to another "
                "drive type\") only if you know the objects mean the same on both")
                .arg(set.drive.type(), set.drive.info, drive.type(), drive.info));
    QSet<Compax3ObjectId> inFile;
    QList<Compax3Write> writes;
    for (const Compax3ParameterValue& value : set.values) {
        inFile.insert(value.id);
        if (!options.only.isEmpty() && !options.only.contains(value.id)) continue;
        // A control word or function goes to the write path unchecked: it
        // sends nothing to it and says why.
        if (!compax3NeverFromAFile(dictionary, value.id).isEmpty()) {
            writes << Compax3Write{value.id, value.value, {}};
            continue;
        }
        const Result<QString> wire = compax3WireValueFor(dictionary, value.id, value.value);
        if (!wire)
            return Error::invalidData(
                QCoreApplication::translate("cambench::usecases",
                                            "the file's value of %1 cannot be written: %2. "
                                            "Nothing was written")
                    .arg(value.id.text(), wire.error().message));
        writes << Compax3Write{value.id, value.value, *wire};
    }
    for (const Compax3ObjectId& id : options.only)
        if (!inFile.contains(id))
            return Error::usage(
                QCoreApplication::translate("cambench::usecases",
                                            "%1 is not in the file: nothing was written")
                    .arg(id.text()));
    return writes;
}

// Stores each set an object was written into (1904.n = $32,
// comm/compax3/README.md C1): a function, written once each, nothing to
// read back. `lines` are writeCompax3Objects' for `writes`, in order.
QList<OutcomeLine> storeSets(Compax3Device& device, const QList<Compax3Write>& writes,
                             const QList<OutcomeLine>& lines) {
    QList<int> sets;
    for (int i = 0; i < writes.size() && i < lines.size(); ++i) {
        const Compax3ObjectId& id = writes.at(i).id;
        if (lines.at(i).state == WriteState::Written && id.index >= 1901 && id.index <= 1908 &&
            id.index != comm::compax3StoreSet(0).index && !sets.contains(id.subindex))
            sets << id.subindex;
    }
    std::sort(sets.begin(), sets.end());
    QList<OutcomeLine> stores;
    Error stopped;
    for (int set : sets) {
        const QString what =
            QCoreApplication::translate("cambench::usecases",
                                        "store set %1 in the drive's flash (1904.%1 = $32)")
                .arg(set);
        if (stopped.kind != ErrorKind::None) {
            stores << notSentLine(what, stopped);
            continue;
        }
        const Status stored = device.writeObject(comm::compax3StoreSet(set),
                                                 compax3HexText(comm::kCompax3StoreSetsValue));
        const WriteState state = stored ? WriteState::Written : WriteState::Unknown;
        const Error error = stored ? Error{} : stored.error();
        stores << OutcomeLine{what, state, outcomeText(what, state, {}, error, {}), error};
        if (!stored && stopsTheWork(error)) stopped = error;
    }
    return stores;
}

}  // namespace

OutcomeTally writeCompax3Objects(Compax3Device& device, const QList<Compax3Write>& writes,
                                 const Compax3Dictionary& dictionary, Compax3WriteSource source,
                                 const UseCaseProgress& progress) {
    QList<OutcomeLine> lines;
    Error stopped;
    for (int i = 0; i < writes.size(); ++i) {
        const Compax3Write& wanted = writes.at(i);
        const QString what = label(wanted.id, dictionary);
        if (const QString never = refusedFrom(source, dictionary, wanted.id); !never.isEmpty()) {
            lines << notSentLine(what, Error::usage(never));
            continue;
        }
        if (stopped.kind == ErrorKind::None && progress.cancelled()) stopped = Error::cancelled();
        if (stopped.kind != ErrorKind::None) {
            lines << notSentLine(what, stopped);
            continue;
        }
        progress.report(i, writes.size(),
                        QCoreApplication::translate("cambench::usecases", "Writing objects"));
        const Compax3ObjectInfo* info = dictionary.find(wanted.id);
        if (info && !info->readable()) {
            // A function (1904.n) typed by a person: nothing to compare or
            // read back.
            const Status write = device.writeObject(wanted.id, wanted.wire);
            const WriteState state = write ? WriteState::Written : WriteState::Unknown;
            lines << OutcomeLine{what, state,
                                 outcomeText(what, state, {}, write ? Error{} : write.error(), {}),
                                 write ? Error{} : write.error()};
            if (!write && stopsTheWork(write.error())) stopped = write.error();
            continue;
        }
        const Result<QString> old = readConfirmed(device, wanted.id, wanted.value);
        if (!old) {
            const Error why =
                comm::compax3RefusalMeansAbsent(old.error(), device.dictionary().refusals())
                    ? Error::device(old.error().deviceCode,
                                    QCoreApplication::translate(
                                        "cambench::usecases", "not on this drive (%1): not written")
                                        .arg(old.error().message))
                    : old.error();
            lines << notSentLine(what, why);
            if (stopsTheWork(old.error())) stopped = old.error();
            continue;
        }
        if (compax3SameValue(*old, wanted.value)) {
            lines << OutcomeLine{what,
                                 WriteState::Unchanged,
                                 outcomeText(what, WriteState::Unchanged, *old, {}, {}),
                                 {}};
            continue;
        }
        const Status write = device.writeObject(wanted.id, wanted.wire);
        const Result<QString> back = readConfirmed(device, wanted.id, wanted.value);
        if (write && back && compax3SameValue(*back, wanted.value)) {
            lines << OutcomeLine{what,
                                 WriteState::Written,
                                 outcomeText(what, WriteState::Written, *back, {}, {}),
                                 {}};
            continue;
        }
        const Error error =
            write
                ? Error::device(0, QCoreApplication::translate(
                                       "cambench::usecases", "the drive took it but reads back %1")
                                       .arg(back ? *back : QString()))
                : write.error();
        lines << failedWriteLine(what, error, back.ok(), back && compax3SameValue(*back, *old),
                                 back && compax3SameValue(*back, wanted.value),
                                 back ? *back : QString());
        if (stopsTheWork(error)) stopped = error;
        if (!back && stopsTheWork(back.error())) stopped = back.error();
    }
    progress.report(writes.size(), writes.size(),
                    QCoreApplication::translate("cambench::usecases", "Written"));
    return OutcomeTally(lines);
}

namespace {

// The checks before the first byte: the drive's identity, its type, each
// value; the writes they leave.
Result<QList<Compax3Write>> checkedWrites(Compax3Device& device, const Compax3ParameterSet& set,
                                          const Compax3Dictionary& dictionary,
                                          const Compax3RestoreOptions& options) {
    const Result<Compax3Identity> identity = device.identity();
    if (!identity) return identity.error();
    if (const Status target = checkRestoreTarget(
            set.drive.deviceIdentity(), identity->deviceIdentity(), options.replacement,
            QCoreApplication::translate("cambench::usecases", "The parameter set"));
        !target)
        return target.error();
    return checkRestore(*identity, set, dictionary, options);
}

}  // namespace

Result<QList<BackupDifference>> planCompax3Restore(Compax3Device& device,
                                                   const Compax3ParameterSet& set,
                                                   const Compax3Dictionary& dictionary,
                                                   const Compax3RestoreOptions& options,
                                                   const UseCaseProgress& progress) {
    if (const Result<QList<Compax3Write>> checked = checkedWrites(device, set, dictionary, options);
        !checked)
        return checked.error();
    const Result<Compax3Comparison> comparison =
        compareCompax3Parameters(device, set, dictionary, progress);
    if (!comparison) return comparison.error();
    QList<BackupDifference> changes;
    // The comparison's old side is the file's: a plan's is the drive's. An
    // object the file records absent is left as it is (not written).
    for (const Compax3Difference& difference : comparison->differences) {
        if (difference.absentInFile) continue;
        if (!options.only.isEmpty() && !options.only.contains(difference.id)) continue;
        Compax3Difference towardsFile = difference;
        std::swap(towardsFile.fileValue, towardsFile.driveValue);
        changes << compax3ObjectDifference(towardsFile, nameOf(set, dictionary, difference.id));
    }
    return changes;
}

Result<OutcomeTally> restoreCompax3Parameters(Compax3Device& device, const Compax3ParameterSet& set,
                                              const Compax3Dictionary& dictionary,
                                              const Compax3RestoreOptions& options,
                                              const UseCaseProgress& progress) {
    const Result<QList<Compax3Write>> checked = checkedWrites(device, set, dictionary, options);
    if (!checked) return checked.error();
    const QList<Compax3Write> writes = *checked;
    const OutcomeTally tally =
        writeCompax3Objects(device, writes, dictionary, Compax3WriteSource::File, progress);
    if (!options.store) return tally;
    // The store makes the sets permanent: only after every object was
    // written or unchanged.
    QList<OutcomeLine> lines = tally.lines();
    if (!tally.complete()) {
        const QString what = QCoreApplication::translate(
            "cambench::usecases", "store the sets in the drive's flash (1904.n = $32)");
        lines << notSentLine(
            what, Error::usage(QCoreApplication::translate(
                      "cambench::usecases", "not stored, because not every object was written")));
        return OutcomeTally(lines);
    }
    lines << storeSets(device, writes, tally.lines());
    return OutcomeTally(lines);
}

}  // namespace cambench::usecases
