// backup-line / verify-line: every device of a Multiuser line into one
// folder with a manifest, on the line-backup use case.
#include "app/cli/camcon/camcon_commands.h"
#include "app/cli/cli_output.h"
#include "app/cli/exit_codes.h"

#include "comm/camcon/usecases/line_backup.h"

#include <QDateTime>
#include <QDir>

namespace cambench::cli {

namespace {

using comm::CamConDevice;
using comm::JobContext;
using usecases::UseCaseProgress;

Status needsBus(const CliSession& session, const QString& command) {
    if (session.options().isBus()) return success();
    return Error::unsupported(
        QStringLiteral("%1 works on a Multiuser line or a Cam-BUS, not over the %2 protocol; "
                       "leave --protocol out (then it speaks Multiuser) or use --protocol cambus")
            .arg(command, session.options().protocol));
}

// The bar shows the device being worked on.
usecases::DeviceProgressFn barFor(JobContext& job) {
    return [&job](int device, qint64 done, qint64 total, const QString& text) {
        job.progress(done, total, QStringLiteral("device %1: %2").arg(device).arg(text));
    };
}

UseCaseProgress cancelOnly(JobContext& job) {
    return UseCaseProgress({}, [&job] { return job.cancelled(); });
}

QString lineDescription(const CliSession& session) {
    const GlobalOptions& options = session.options();
    return QStringLiteral("%1, %2, %3 baud")
        .arg(options.port, options.protocol)
        .arg(options.effectiveBaud());
}

}  // namespace

int runBackupLine(CliSession& session, CommandArgs& args) {
    usecases::LineBackupOptions options;
    options.resume = args.takeFlag(QStringLiteral("--resume"));
    const Result<QString> directory =
        args.takeOption(QStringLiteral("--output-dir"), QStringLiteral("-o"));
    if (!directory) return reportError(directory.error());
    const Result<QString> devices = args.takeOption(QStringLiteral("--devices"));
    if (!devices) return reportError(devices.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    if (directory->isEmpty())
        return reportError(Error::usage(QStringLiteral("backup-line needs -o DIR")));
    if (const Status bus = needsBus(session, QStringLiteral("backup-line")); !bus)
        return reportError(bus.error());
    if (!devices->isEmpty()) {
        const Result<QList<int>> numbers =
            parseDeviceNumbers(*devices, QStringLiteral("--devices"));
        if (!numbers) return reportError(numbers.error());
        options.devices = *numbers;
    }
    options.directory = *directory;
    options.lineDescription = lineDescription(session);

    session.setShowProgress(true);
    const QDateTime started = QDateTime::currentDateTimeUtc();
    const Result<LineManifest> manifest = runOnCamCon<LineManifest>(
        session, QStringLiteral("backup-line"), [options](CamConDevice& device, JobContext& job) {
            return usecases::backupLine(device, options, cancelOnly(job), barFor(job));
        });
    if (!manifest) return reportError(manifest.error());
    QString text;
    int saved = 0;
    int failed = 0;
    for (const LineManifestEntry& entry : manifest->devices) {
        if (entry.outcome == LineManifestEntry::Outcome::Saved) {
            ++saved;
            const bool earlier = entry.time < started;
            text += QStringLiteral("device %1: saved %2%3\n")
                        .arg(entry.device)
                        .arg(entry.file)
                        .arg(earlier ? QStringLiteral(" (by an earlier run, file checked)")
                                     : QString());
        } else {
            ++failed;
            text += QStringLiteral("device %1: FAILED: %2\n").arg(entry.device).arg(entry.message);
        }
    }
    const QString manifestPath = QDir(*directory).filePath(QLatin1String(kLineManifestName));
    text += QStringLiteral("%1 devices: %2 saved, %3 failed; manifest %4\n")
                .arg(manifest->devices.size())
                .arg(saved)
                .arg(failed)
                .arg(manifestPath);
    printOut(text);
    if (failed == 0) return ExitOk;
    printError(QStringLiteral("%1 of %2 devices were not backed up; run the same command with "
                              "--resume once they answer")
                   .arg(failed)
                   .arg(manifest->devices.size()));
    return ExitCommunication;
}

int runVerifyLine(CliSession& session, CommandArgs& args) {
    const Result<QString> directory = args.takeRequiredPositional(QStringLiteral("a folder DIR"));
    if (!directory) return reportError(directory.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    if (const Status bus = needsBus(session, QStringLiteral("verify-line")); !bus)
        return reportError(bus.error());
    session.setShowProgress(true);
    const QString folder = *directory;
    const Result<QList<usecases::LineVerifyEntry>> entries =
        runOnCamCon<QList<usecases::LineVerifyEntry>>(
            session, QStringLiteral("verify-line"),
            [folder](CamConDevice& device, JobContext& job) {
                return usecases::verifyLine(device, folder, cancelOnly(job), barFor(job));
            });
    if (!entries) return reportError(entries.error());
    QString text;
    int equal = 0;
    for (const usecases::LineVerifyEntry& entry : *entries) {
        text += entry.text + QLatin1Char('\n');
        equal += entry.equal ? 1 : 0;
    }
    text += QStringLiteral("%1 devices: %2 equal their images, %3 do not or were not verified\n")
                .arg(entries->size())
                .arg(equal)
                .arg(entries->size() - equal);
    printOut(text);
    return equal == entries->size() && !entries->isEmpty() ? ExitOk : ExitDevice;
}

}  // namespace cambench::cli
