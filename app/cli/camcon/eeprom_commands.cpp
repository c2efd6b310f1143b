// backup, restore, verify: the whole EEPROM as an image file with its
// content decoded, on the backup/restore use case
// (comm/camcon/usecases/backup_restore.h) and the CamCon's backup part.
#include "app/cli/backup_output.h"
#include "app/cli/camcon/camcon_commands.h"
#include "app/cli/cli_output.h"
#include "app/cli/exit_codes.h"

#include "comm/camcon/usecases/backup_restore.h"
#include "model/camcon/camcon_family_id.h"
#include "model/camcon/eeprom_image_file.h"

namespace cambench::cli {

using comm::CamConDevice;
using comm::JobContext;
using usecases::UseCaseProgress;

int runBackup(CliSession& session, CommandArgs& args) {
    const Result<QString> path =
        args.takeOption(QStringLiteral("--output-file"), QStringLiteral("-o"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    if (path->isEmpty()) return reportError(Error::usage(QStringLiteral("backup needs -o FILE")));
    session.setShowProgress(true);
    const QString file = *path;
    const Result<EepromImage> image = runOnCamCon<EepromImage>(
        session, QStringLiteral("backup"), [file](CamConDevice& device, JobContext& job) {
            return usecases::backupToFile(device, file, UseCaseProgress::of(job));
        });
    if (!image) return reportError(image.error());
    printOut(QStringLiteral("saved %1 EEPROM blocks (%2 bytes) to %3\n")
                 .arg(image->blocks.size())
                 .arg(image->totalBytes())
                 .arg(*path));
    return ExitOk;
}

int runRestore(CliSession& session, CommandArgs& args) {
    usecases::RestoreOptions options;
    // --force is the older name of --replacement (it was "restore over an
    // identity mismatch"): both accept the device answering in place of the
    // image's.
    const bool replacement = args.takeFlag(QStringLiteral("--replacement"));
    if (args.takeFlag(QStringLiteral("--force")) || replacement)
        options.replacement = ReplacementConsent::any();
    options.safetyBackup = !args.takeFlag(QStringLiteral("--no-safety-backup"));
    const Result<QString> path = args.takeRequiredPositional(QStringLiteral("an image FILE"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());

    // Hash, version, block 0 and every block length are checked before the
    // device is even contacted.
    const Result<EepromImage> image = loadEepromImage(*path);
    if (!image) return reportError(image.error());

    session.setShowProgress(true);
    const QString file = *path;
    const EepromImage blocks = *image;
    const Result<usecases::RestoreReport> report = runOnCamCon<usecases::RestoreReport>(
        session, QStringLiteral("restore"),
        [file, blocks, options](CamConDevice& device, JobContext& job) {
            return usecases::restoreImage(device, blocks, file, options, UseCaseProgress::of(job));
        });
    if (!report) return reportError(report.error());
    if (!report->linkNote.isEmpty() && report->state != usecases::RestoredState::Unchanged)
        printError(QStringLiteral("note: %1").arg(report->linkNote));
    if (!report->safetyBackupPath.isEmpty()) {
        printError(QStringLiteral("safety backup of the device saved to %1")
                       .arg(report->safetyBackupPath));
    }
    if (!report->ok()) {
        Error error = report->error;
        if (report->state == usecases::RestoredState::ErasedOrPartial)
            error.message += QStringLiteral(" Nothing else was changed.");
        return reportError(error);
    }
    printOut(QStringLiteral("restored %1 EEPROM blocks from %2\n").arg(report->blocks).arg(*path));
    return ExitOk;
}

// Through the CamCon's backup part: the blocks compared, and where they
// differ the content item by item ("program 2, output 9: cam 300–310
// removed"), the same as `machine verify`.
int runVerify(CliSession& session, CommandArgs& args) {
    const Result<QString> path = args.takeRequiredPositional(QStringLiteral("an image FILE"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    return verifyWithPart(session, camconFamilyId, *path);
}

}  // namespace cambench::cli
