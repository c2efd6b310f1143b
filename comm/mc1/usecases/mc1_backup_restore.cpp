#include "mc1_backup_restore.h"

#include "comm/mc1/mc1_parameters.h"

#include <QCoreApplication>

namespace cambench::usecases {

namespace {

using comm::Mc1Capability;
using comm::Mc1Device;
using comm::Mc1Point;

// What the controller holds of everything `like` holds (the same
// variables, the flags if it has them, the same memory ranges).
Result<Mc1Backup> readLike(Mc1Device& device, const Mc1Backup& like,
                           const UseCaseProgress& progress) {
    Mc1Backup now;
    now.variant = comm::mc1VariantKey(device.variant());
    now.taken = QDateTime::currentDateTimeUtc();
    qint64 total = like.variables.size() + (like.flags.isEmpty() ? 0 : 1) + like.memory.size();
    qint64 done = 0;
    for (auto it = like.variables.begin(); it != like.variables.end(); ++it) {
        if (progress.cancelled()) return Error::cancelled();
        const Result<qint64> value = device.readVariable(it.key());
        if (!value) return value.error();
        now.variables.insert(it.key(), *value);
        progress.report(++done, total,
                        QCoreApplication::translate("cambench::usecases", "Reading variables"));
    }
    if (!like.flags.isEmpty()) {
        const Result<QByteArray> page = device.readExternalPage(quint8(like.flagPage), {});
        if (!page) return page.error();
        now.flagPage = like.flagPage;
        now.flags = *page;
        progress.report(++done, total,
                        QCoreApplication::translate("cambench::usecases", "Reading flags"));
    }
    for (const Mc1MemoryRange& range : like.memory) {
        if (progress.cancelled()) return Error::cancelled();
        const Result<QByteArray> bytes =
            device.readMemory(range.address, int(range.data.size()), {});
        if (!bytes) return bytes.error();
        now.memory << Mc1MemoryRange{range.address, *bytes};
        progress.report(++done, total,
                        QCoreApplication::translate("cambench::usecases", "Reading memory"));
    }
    return now;
}

// Refuses (nothing written) a file the controller cannot take.
Status checkFits(Mc1Device& device, const Mc1Backup& backup) {
    const Result<comm::Mc1Variant> variant = device.ensureIdentified();
    if (!variant) return variant.error();
    const QString controller = comm::mc1VariantName(*variant);
    if (backup.mc200() != comm::isMc200(*variant))
        return Error::invalidData(
            QCoreApplication::translate("cambench::usecases",
                                        "the file was taken from an %1, the controller is an %2 "
                                        "(variables of other widths, flags elsewhere): nothing was "
                                        "written")
                .arg(backup.mc200() ? QStringLiteral("MC200") : QStringLiteral("MC100"),
                     controller));
    if (!backup.flags.isEmpty() && backup.flagPage != comm::mc1ExternalFlagPage(backup.mc200()))
        return Error::invalidData(QCoreApplication::translate(
                                      "cambench::usecases",
                                      "the file's flags are on page %1, the %2 keeps them on page "
                                      "%3: nothing was written")
                                      .arg(backup.flagPage)
                                      .arg(controller)
                                      .arg(comm::mc1ExternalFlagPage(backup.mc200())));
    if (!backup.memory.isEmpty() && !device.has(Mc1Capability::MemoryWrite))
        return Error::invalidData(
            QCoreApplication::translate("cambench::usecases",
                                        "the file holds memory ranges, which the %1 cannot write "
                                        "(an MC200 V2 can): nothing was written")
                .arg(controller));
    return success();
}

}  // namespace

Mc1BackupScope defaultMc1BackupScope(comm::Mc1Variant variant) {
    const comm::Mc1VariableRange range = comm::mc1VariableRange(variant);
    Mc1BackupScope scope;
    scope.firstVariable = range.first;
    scope.lastVariable = range.last;
    return scope;
}

Result<Mc1Backup> takeMc1Backup(Mc1Device& device, const Mc1BackupScope& scope,
                                const UseCaseProgress& progress) {
    const Result<comm::Mc1Variant> variant = device.ensureIdentified();
    if (!variant) return variant.error();
    const Result<DeviceIdentity> identity = device.readIdentity();
    if (!identity) return identity.error();
    if (!scope.memory.isEmpty() && !device.has(Mc1Capability::MemoryRead))
        return Error::unsupported(
            QCoreApplication::translate(
                "cambench::usecases",
                "the %1 has no memory telegrams (an MC200 has): leave out --mem")
                .arg(comm::mc1VariantName(*variant)));
    Mc1Backup like;
    for (int n = scope.firstVariable; n <= scope.lastVariable; ++n) like.variables.insert(n, 0);
    if (scope.flags) {
        like.flagPage = comm::mc1ExternalFlagPage(comm::isMc200(*variant));
        like.flags = QByteArray(256, '\0');
    }
    for (const auto& [address, length] : scope.memory)
        like.memory << Mc1MemoryRange{address, QByteArray(length, '\0')};
    const Result<Mc1Backup> read = readLike(device, like, progress);
    if (!read) return read.error();
    Mc1Backup backup = *read;
    backup.identity = *identity;
    backup.toolVersion = QStringLiteral(CAMBENCH_VERSION);
    return backup;
}

Result<Mc1VerifyReport> verifyMc1Backup(Mc1Device& device, const Mc1Backup& backup,
                                        const UseCaseProgress& progress) {
    if (const Status fits = checkFits(device, backup); !fits) return fits.error();
    const Result<Mc1Backup> now = readLike(device, backup, progress);
    if (!now) return now.error();
    Mc1VerifyReport report;
    report.compared = mc1ItemCount(backup);
    report.items = diffMc1Backups(backup, *now);
    for (const BackupDifference& item : report.items) report.differences << item.text;
    return report;
}

namespace {

// The controller the file is for, and what it holds now (the file's
// items); an error when another controller answers (without consent) or
// the file does not fit: nothing was written.
Result<Mc1Backup> readForRestore(Mc1Device& device, const Mc1Backup& backup,
                                 const ReplacementConsent& replacement,
                                 const UseCaseProgress& progress) {
    const Result<DeviceIdentity> identity = device.readIdentity();
    if (!identity) return identity.error();
    if (const Status target =
            checkRestoreTarget(backup.identity, *identity, replacement,
                               QCoreApplication::translate("cambench::usecases", "The backup"));
        !target)
        return target.error();
    if (const Status fits = checkFits(device, backup); !fits) return fits.error();
    return readLike(device, backup, progress);
}

}  // namespace

Result<QList<BackupDifference>> planMc1Restore(Mc1Device& device, const Mc1Backup& backup,
                                               const ReplacementConsent& replacement,
                                               const UseCaseProgress& progress) {
    const Result<Mc1Backup> now = readForRestore(device, backup, replacement, progress);
    if (!now) return now.error();
    return diffMc1Backups(*now, backup);
}

Result<OutcomeTally> restoreMc1Backup(Mc1Device& device, const Mc1Backup& backup,
                                      const ReplacementConsent& replacement,
                                      const UseCaseProgress& progress) {
    const Result<Mc1Backup> now =
        readForRestore(device, backup, replacement, progress.slice(0, 1, 2));
    if (!now) return now.error();
    const UseCaseProgress writing = progress.slice(1, 1, 2);
    QList<OutcomeLine> lines;
    Error stopped;  // the line failed: the rest is not sent
    const auto notSent = [&](const QString& label) {
        lines << OutcomeLine{label, WriteState::NotSent,
                             outcomeText(label, WriteState::NotSent, {}, stopped, {}), stopped};
    };
    const auto unchanged = [&](const QString& label, const QString& actual) {
        lines << OutcomeLine{label,
                             WriteState::Unchanged,
                             outcomeText(label, WriteState::Unchanged, actual, {}, {}),
                             {}};
    };
    const auto written = [&](const QString& label, const QString& actual) {
        lines << OutcomeLine{label,
                             WriteState::Written,
                             outcomeText(label, WriteState::Written, actual, {}, {}),
                             {}};
    };
    const auto failed = [&](const Error& error) {
        if (error.kind == ErrorKind::Communication || error.kind == ErrorKind::Cancelled)
            stopped = error;
    };
    const qint64 total = backup.variables.size() + backup.memory.size() + 1;
    qint64 done = 0;

    for (auto it = backup.variables.begin(); it != backup.variables.end(); ++it) {
        const QString label = QStringLiteral("V%1").arg(it.key());
        const qint64 old = now->variables.value(it.key());
        if (stopped.kind != ErrorKind::None || writing.cancelled()) {
            if (writing.cancelled() && stopped.kind == ErrorKind::None)
                stopped = Error::cancelled();
            notSent(label);
            continue;
        }
        if (old == it.value()) {
            unchanged(label, QString::number(old));
        } else if (const Status w = device.writeVariable(it.key(), it.value()); w) {
            written(label, QString::number(it.value()));
        } else {
            const Result<qint64> back = device.readVariable(it.key());
            lines << failedWriteLine(label, w.error(), back.ok(), back && *back == old,
                                     back && *back == it.value(),
                                     back ? QString::number(*back) : QString());
            failed(w.error());
        }
        writing.report(++done, total,
                       QCoreApplication::translate("cambench::usecases", "Writing variables"));
    }

    for (int bit = 0; bit < backup.flags.size() * 8; ++bit) {
        const bool wanted = quint8(backup.flags.at(bit >> 3)) & (1u << (bit & 7));
        const bool old = quint8(now->flags.at(bit >> 3)) & (1u << (bit & 7));
        const Mc1Point point = comm::mc1ExternalFlagAt(bit, backup.mc200());
        const QString label = comm::mc1PointText(point);
        if (wanted == old) continue;  // 2048 flags: only the differing ones are listed
        if (stopped.kind != ErrorKind::None) {
            notSent(label);
            continue;
        }
        const Result<bool> back = device.writePoint(point, wanted);
        if (back && *back == wanted) {
            written(label, wanted ? QStringLiteral("1") : QStringLiteral("0"));
        } else if (back) {
            lines << failedWriteLine(
                label,
                Error::device(0, QCoreApplication::translate("cambench::usecases", "read back %1")
                                     .arg(*back ? 1 : 0)),
                true, *back == old, false, *back ? QStringLiteral("1") : QStringLiteral("0"));
        } else {
            lines << failedWriteLine(label, back.error(), false, false, false, {});
            failed(back.error());
        }
    }
    if (!backup.flags.isEmpty()) {
        const int differing =
            int(std::count_if(lines.begin(), lines.end(), [](const OutcomeLine& l) {
                return l.label.startsWith(QLatin1Char('M'));
            }));
        const QString label =
            QCoreApplication::translate("cambench::usecases", "the other %1 flags")
                .arg(backup.flags.size() * 8 - differing);
        unchanged(label, {});
    }
    writing.report(++done, total,
                   QCoreApplication::translate("cambench::usecases", "Writing flags"));

    for (int i = 0; i < backup.memory.size(); ++i) {
        const Mc1MemoryRange& range = backup.memory.at(i);
        for (int at = 0; at < range.data.size(); at += comm::kMc1MaxMemoryWrite) {
            const QByteArray wanted = range.data.mid(at, comm::kMc1MaxMemoryWrite);
            const QByteArray old = now->memory.at(i).data.mid(at, comm::kMc1MaxMemoryWrite);
            const int address = range.address + at;
            const QString label = mc1MemoryLabel(address, int(wanted.size()));
            if (stopped.kind != ErrorKind::None) {
                notSent(label);
                continue;
            }
            if (wanted == old) {
                unchanged(label, {});
                continue;
            }
            const Status w = device.writeMemory(address, wanted, {});
            const Result<QByteArray> back = device.readMemory(address, int(wanted.size()), {});
            if (w && back && *back == wanted) {
                written(label, {});
            } else {
                const Error error =
                    w ? Error::device(0, QCoreApplication::translate(
                                             "cambench::usecases",
                                             "the bytes read back differ from those written"))
                      : w.error();
                lines << failedWriteLine(label, error, back.ok(), back && *back == old,
                                         back && *back == wanted, {});
                failed(error);
            }
        }
        writing.report(++done, total,
                       QCoreApplication::translate("cambench::usecases", "Writing memory"));
    }
    return OutcomeTally(lines);
}

}  // namespace cambench::usecases
