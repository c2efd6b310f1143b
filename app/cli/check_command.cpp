// `check`: each provisional reading of ours about the connected device's
// family tried on it, reading only (comm/usecases/device_check.h), one
// verdict a line or as JSON; the report a technician sends back so that
// our tables can be corrected. Exit 1 when any reading was refuted.
#include "cli_output.h"
#include "commands.h"
#include "exit_codes.h"

#include "comm/usecases/device_check.h"

#include <QJsonDocument>

namespace cambench::cli {

int runCheck(CliSession& session, CommandArgs& args) {
    const bool json = args.takeFlag(QStringLiteral("--json"));
    const Result<QString> path =
        args.takeOption(QStringLiteral("--output-file"), QStringLiteral("-o"));
    if (!path) return reportError(path.error());
    // The families' table files (--parameters, --dictionary), read and
    // parsed before the connection opens.
    const usecases::CheckRegistry& checks = usecases::CheckRegistry::instance();
    QList<usecases::CheckTable> tables;
    for (const QString& option : checks.tableOptions()) {
        const Result<QString> file = args.takeOption(option);
        if (!file) return reportError(file.error());
        if (file->isEmpty()) continue;
        const Result<usecases::CheckTable> table = checks.loadTable(option, *file);
        if (!table) return reportError(table.error());
        tables << *table;
    }
    if (const Status done = args.finish(); !done) return reportError(done.error());
    session.setShowProgress(true);
    const Result<usecases::CheckReport> report =
        session.run<comm::DeviceConnection, usecases::CheckReport>(
            QStringLiteral("check"),
            [tables](comm::DeviceConnection& device, comm::JobContext& job) {
                return usecases::checkDevice(device, usecases::UseCaseProgress::of(job), tables);
            });
    if (!report) return reportError(report.error());
    const QByteArray bytes =
        json ? QJsonDocument(usecases::checkReportJson(*report)).toJson(QJsonDocument::Indented)
             : usecases::checkReportText(*report).toUtf8();
    if (const Status written = writeOutput(*path, bytes); !written)
        return reportError(written.error());
    return report->anyRefuted() ? ExitDevice : ExitOk;
}

}  // namespace cambench::cli
