// mc mem, mc backup, mc verify, mc restore: through the MC-1 use cases
// (comm/mc1/usecases), the same the GUI runs.
#include "mc1_commands.h"

#include "app/cli/backup_output.h"
#include "app/cli/cli_output.h"
#include "app/cli/exit_codes.h"
#include "app/cli/outcome_output.h"

#include "comm/mc1/mc1_parameters.h"
#include "comm/mc1/usecases/mc1_backup_restore.h"
#include "model/mc1/mc1_family_id.h"

#include <QRegularExpression>

namespace cambench::cli {

namespace {

using comm::JobContext;
using comm::Mc1Device;
using usecases::UseCaseProgress;

// "ADDR:LEN", e.g. 0x1000:256.
Result<std::pair<int, int>> parseMemoryRange(const QString& text) {
    const QStringList parts = text.split(QLatin1Char(':'));
    if (parts.size() != 2)
        return Error::usage(
            QStringLiteral("--mem needs ADDR:LEN, e.g. 0x1000:256, not \"%1\"").arg(text));
    const Result<int> address =
        parseMc1Address(parts.at(0), QStringLiteral("--mem ADDR"), comm::kMc1MemorySize - 1);
    if (!address) return address.error();
    const Result<int> length =
        parseMc1Address(parts.at(1), QStringLiteral("--mem LEN"), comm::kMc1MemorySize - *address);
    if (!length) return length.error();
    if (*length == 0) return Error::usage(QStringLiteral("--mem LEN must be 1 or more"));
    return std::pair<int, int>{*address, *length};
}

// The FILE argument of verify and restore, loaded and checked (hash,
// variant, values) before the line is opened.
Result<Mc1Backup> takeBackupFile(CommandArgs& args, QString& path) {
    const Result<QString> given = args.takeRequiredPositional(QStringLiteral("a backup FILE"));
    if (!given) return given.error();
    if (const Status done = args.finish(); !done) return done.error();
    path = *given;
    return loadMc1Backup(path);
}

}  // namespace

int runMc1Memory(CliSession& session, CommandArgs& args) {
    const Result<QString> verb = takeVerb(args, {QStringLiteral("read"), QStringLiteral("write")});
    if (!verb) return reportError(verb.error());
    const Result<QString> path =
        args.takeOption(QStringLiteral("--output-file"), QStringLiteral("-o"));
    if (!path) return reportError(path.error());
    const Result<QString> addressText = args.takeRequiredPositional(QStringLiteral("an ADDR"));
    if (!addressText) return reportError(addressText.error());
    const Result<int> address =
        parseMc1Address(*addressText, QStringLiteral("ADDR"), comm::kMc1MemorySize - 1);
    if (!address) return reportError(address.error());
    if (*verb == QLatin1String("read")) {
        const Result<QString> lengthText = args.takeRequiredPositional(QStringLiteral("a LEN"));
        if (!lengthText) return reportError(lengthText.error());
        const Result<int> length =
            parseMc1Address(*lengthText, QStringLiteral("LEN"), comm::kMc1MemorySize - *address);
        if (!length) return reportError(length.error());
        if (const Status done = args.finish(); !done) return reportError(done.error());
        session.setShowProgress(true);
        const Result<QByteArray> bytes = runOnMc1<QByteArray>(
            session, QStringLiteral("mc mem read"),
            [a = *address, n = *length](Mc1Device& device, JobContext& job) {
                return device.readMemory(a, n, [&job](qint64 done, qint64 total) {
                    job.progress(done, total, QStringLiteral("reading memory"));
                });
            });
        if (!bytes) return reportError(bytes.error());
        if (!path->isEmpty()) {
            const Status written = writeOutput(*path, *bytes);
            return written ? ExitOk : reportError(written.error());
        }
        printOut(comm::mc1HexLines(*address, *bytes));
        return ExitOk;
    }
    const Result<QString> hex = args.takeRequiredPositional(QStringLiteral("the bytes in HEX"));
    if (!hex) return reportError(hex.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    static const QRegularExpression pattern(QStringLiteral("^([0-9a-fA-F]{2})+$"));
    if (!pattern.match(*hex).hasMatch())
        return reportError(Error::usage(
            QStringLiteral("HEX must be pairs of hexadecimal digits, e.g. 0a0b0c, not \"%1\"")
                .arg(*hex)));
    const QByteArray bytes = QByteArray::fromHex(hex->toLatin1());
    const Result<QByteArray> back = runOnMc1<QByteArray>(
        session, QStringLiteral("mc mem write"),
        [a = *address, bytes](Mc1Device& device, JobContext&) -> Result<QByteArray> {
            if (const Status written = device.writeMemory(a, bytes, {}); !written)
                return written.error();
            return device.readMemory(a, int(bytes.size()), {});
        });
    if (!back) return reportError(back.error());
    printOut(comm::mc1HexLines(*address, *back));
    if (*back != bytes)
        return reportError(
            Error::device(0, QStringLiteral("the memory reads back other bytes than written")));
    return ExitOk;
}

int runMc1Backup(CliSession& session, CommandArgs& args) {
    const Result<QString> path =
        args.takeOption(QStringLiteral("--output-file"), QStringLiteral("-o"));
    if (!path) return reportError(path.error());
    const Result<QString> vars = args.takeOption(QStringLiteral("--vars"));
    if (!vars) return reportError(vars.error());
    const bool noFlags = args.takeFlag(QStringLiteral("--no-flags"));
    QList<std::pair<int, int>> memory;
    for (;;) {
        const Result<QString> range = args.takeOption(QStringLiteral("--mem"));
        if (!range) return reportError(range.error());
        if (range->isEmpty()) break;
        const Result<std::pair<int, int>> parsed = parseMemoryRange(*range);
        if (!parsed) return reportError(parsed.error());
        memory << *parsed;
    }
    if (const Status done = args.finish(); !done) return reportError(done.error());
    if (path->isEmpty())
        return reportError(Error::usage(QStringLiteral("mc backup needs -o FILE")));
    std::optional<std::pair<int, int>> variables;
    if (!vars->isEmpty()) {
        const Result<std::pair<int, int>> parsed =
            parseMc1Range(*vars, QStringLiteral("--vars"), 0, 0xFFFF);
        if (!parsed) return reportError(parsed.error());
        variables = *parsed;
    }
    session.setShowProgress(true);
    const Result<Mc1Backup> backup = runOnMc1<Mc1Backup>(
        session, QStringLiteral("mc backup"),
        [variables, noFlags, memory](Mc1Device& device, JobContext& job) -> Result<Mc1Backup> {
            const Result<comm::Mc1Variant> variant = device.ensureIdentified();
            if (!variant) return variant.error();
            usecases::Mc1BackupScope scope = usecases::defaultMc1BackupScope(*variant);
            if (variables) std::tie(scope.firstVariable, scope.lastVariable) = *variables;
            scope.flags = !noFlags;
            scope.memory = memory;
            return usecases::takeMc1Backup(device, scope, UseCaseProgress::of(job));
        });
    if (!backup) return reportError(backup.error());
    if (const Status saved = saveMc1Backup(*path, *backup); !saved)
        return reportError(saved.error());
    qint64 memoryBytes = 0;
    for (const Mc1MemoryRange& range : backup->memory) memoryBytes += range.data.size();
    printOut(QStringLiteral("saved %1 variables, %2 flags and %3 memory bytes of the %4 to %5\n")
                 .arg(backup->variables.size())
                 .arg(backup->flags.size() * 8)
                 .arg(memoryBytes)
                 .arg(backup->variant, *path));
    return ExitOk;
}

// Through the MC-1's backup part, as `machine verify`: "V12 -5 → 77".
int runMc1Verify(CliSession& session, CommandArgs& args) {
    const Result<QString> path = args.takeRequiredPositional(QStringLiteral("a backup FILE"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    return verifyWithPart(session, mc1FamilyId, *path);
}

int runMc1Restore(CliSession& session, CommandArgs& args) {
    const ReplacementConsent replacement = args.takeFlag(QStringLiteral("--replacement"))
                                               ? ReplacementConsent::any()
                                               : ReplacementConsent{};
    QString path;
    const Result<Mc1Backup> backup = takeBackupFile(args, path);
    if (!backup) return reportError(backup.error());
    session.setShowProgress(true);
    const Result<usecases::OutcomeTally> tally = runOnMc1<usecases::OutcomeTally>(
        session, QStringLiteral("mc restore"),
        [b = *backup, replacement](Mc1Device& device, JobContext& job) {
            return usecases::restoreMc1Backup(device, b, replacement, UseCaseProgress::of(job));
        });
    if (!tally) return reportError(tally.error());
    return printOutcomeTally(*tally);
}

}  // namespace cambench::cli
