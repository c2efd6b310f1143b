#include "backup_output.h"

#include "cli_output.h"
#include "exit_codes.h"

#include "comm/device/device_connection.h"

namespace cambench::cli {

int printComparison(const usecases::BackupComparison& comparison) {
    QString text;
    for (const QString& note : comparison.notes) text += note + QLatin1Char('\n');
    for (const BackupDifference& difference : comparison.differences)
        text += difference.line() + QLatin1Char('\n');
    text += comparison.equal()
                ? QStringLiteral("equal: %1 items compared\n").arg(comparison.compared)
                : QStringLiteral("%1 differences in %2 items compared\n")
                      .arg(comparison.differences.size())
                      .arg(comparison.compared);
    printOut(text);
    return comparison.equal() ? ExitOk : ExitDevice;  // documented: verify exits 1 when it differs
}

int verifyWithPart(CliSession& session, const QString& familyId, const QString& path) {
    const usecases::FamilyBackup* part = usecases::BackupRegistry::instance().find(familyId);
    if (!part)
        return reportError(
            Error::usage(QStringLiteral("the %1 family has no backup").arg(familyId)));
    // A file that would be refused is refused before the line is opened.
    if (const Result<DeviceIdentity> file = part->fileIdentity(path); !file)
        return reportError(file.error());
    session.setShowProgress(true);
    const Result<usecases::BackupComparison> comparison =
        session.run<comm::DeviceConnection, usecases::BackupComparison>(
            QStringLiteral("verify"), [part, path](comm::DeviceConnection&, comm::JobContext& job) {
                return part->verify(job, path);
            });
    if (!comparison) return reportError(comparison.error());
    return printComparison(*comparison);
}

}  // namespace cambench::cli
