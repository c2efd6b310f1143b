// c3 backup, verify, restore: through the Compax3 use cases
// (comm/compax3/usecases), the same the GUI runs.
#include "compax3_commands.h"

#include "app/cli/backup_output.h"
#include "app/cli/cli_output.h"
#include "app/cli/exit_codes.h"
#include "app/cli/outcome_output.h"

#include "comm/compax3/usecases/compax3_parameters.h"
#include "model/compax3/compax3_family_id.h"

namespace cambench::cli {

namespace {

using comm::Compax3Device;
using comm::JobContext;
using usecases::UseCaseProgress;

// --objects/--only LIST: objects separated by commas.
Result<QList<Compax3ObjectId>> takeObjectList(CommandArgs& args, const QString& name) {
    const Result<QString> text = args.takeOption(name);
    if (!text) return text.error();
    if (text->isEmpty()) return QList<Compax3ObjectId>();
    return parseCompax3Objects({*text});
}

Result<Compax3ParameterSet> takeParameterFile(CommandArgs& args, QString& path) {
    const Result<QString> given = args.takeRequiredPositional(QStringLiteral("a parameter FILE"));
    if (!given) return given.error();
    if (const Status done = args.finish(); !done) return done.error();
    path = *given;
    return loadCompax3Parameters(path);
}

}  // namespace

int runCompax3Backup(CliSession& session, CommandArgs& args, const Compax3Dictionary& dictionary) {
    const Result<QString> path =
        args.takeOption(QStringLiteral("--output-file"), QStringLiteral("-o"));
    if (!path) return reportError(path.error());
    const Result<QList<Compax3ObjectId>> given = takeObjectList(args, QStringLiteral("--objects"));
    if (!given) return reportError(given.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    if (path->isEmpty())
        return reportError(Error::usage(QStringLiteral("c3 backup needs -o FILE")));
    const QList<Compax3ObjectId> objects = given->isEmpty() ? dictionary.parameters() : *given;
    session.setShowProgress(true);
    const Result<usecases::Compax3Backup> backup = runOnCompax3<usecases::Compax3Backup>(
        session, QStringLiteral("c3 backup"),
        [objects, dictionary](Compax3Device& device, JobContext& job) {
            return usecases::takeCompax3Parameters(device, objects, dictionary,
                                                   UseCaseProgress::of(job));
        });
    if (!backup) return reportError(backup.error());
    if (const Status saved = saveCompax3Parameters(*path, backup->set); !saved)
        return reportError(saved.error());
    QString text;
    for (const usecases::Compax3Refusal& refusal : backup->notSaved)
        text += QStringLiteral("%1: not saved: %2\n").arg(refusal.id.text(), refusal.reason);
    for (const Compax3ObjectId& id : backup->set.absent)
        text += QStringLiteral("%1: not on this drive (it answered !0002): recorded as absent\n")
                    .arg(id.text());
    for (const usecases::Compax3Refusal& refusal : backup->refused)
        text += QStringLiteral("%1: not saved: %2\n").arg(refusal.id.text(), refusal.reason);
    text += QStringLiteral("saved %1 objects of %2 (serial number %3) to %4")
                .arg(backup->set.values.size())
                .arg(backup->set.drive.info, backup->set.drive.serial, *path);
    if (!backup->set.absent.isEmpty())
        text += QStringLiteral("; %1 objects are not on this drive").arg(backup->set.absent.size());
    text += QLatin1Char('\n');
    printOut(text);
    if (backup->refused.isEmpty()) return ExitOk;
    printError(QStringLiteral("the file is incomplete: the drive refused %1 of %2 objects")
                   .arg(backup->refused.size())
                   .arg(objects.size()));
    return ExitDevice;
}

// Through the Compax3's backup part, as `machine verify`: "1901.4 Set 4
// target 400 → -7.5", with the dictionary the connection holds (--dictionary).
int runCompax3Verify(CliSession& session, CommandArgs& args, const Compax3Dictionary&) {
    const Result<QString> path = args.takeRequiredPositional(QStringLiteral("a parameter FILE"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    return verifyWithPart(session, compax3FamilyId, *path);
}

int runCompax3Restore(CliSession& session, CommandArgs& args, const Compax3Dictionary& dictionary) {
    usecases::Compax3RestoreOptions options;
    if (args.takeFlag(QStringLiteral("--replacement")))
        options.replacement = ReplacementConsent::any();
    options.force = args.takeFlag(QStringLiteral("--force"));
    options.store = args.takeFlag(QStringLiteral("--store"));
    const Result<QList<Compax3ObjectId>> only = takeObjectList(args, QStringLiteral("--only"));
    if (!only) return reportError(only.error());
    options.only = *only;
    QString path;
    const Result<Compax3ParameterSet> set = takeParameterFile(args, path);
    if (!set) return reportError(set.error());
    session.setShowProgress(true);
    const Result<usecases::OutcomeTally> tally = runOnCompax3<usecases::OutcomeTally>(
        session, QStringLiteral("c3 restore"),
        [s = *set, dictionary, options](Compax3Device& device, JobContext& job) {
            return usecases::restoreCompax3Parameters(device, s, dictionary, options,
                                                      UseCaseProgress::of(job));
        });
    if (!tally) return reportError(tally.error());
    return printOutcomeTally(*tally);
}

}  // namespace cambench::cli
