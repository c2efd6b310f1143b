#include "write_output.h"

#include "app/cli/cli_output.h"
#include "app/cli/exit_codes.h"

namespace cambench::cli {

using comm::CamConDevice;
using comm::JobContext;
using usecases::WritePlan;
using usecases::WriteReport;

int runWritePlan(CliSession& session, const QString& title, const usecases::WritePlan& plan) {
    return runWritePlan(session, title,
                        [plan](comm::CamConDevice&,
                               const DeviceInfo&) -> Result<usecases::WritePlan> { return plan; });
}

int runWritePlan(CliSession& session, const QString& title,
                 std::function<Result<WritePlan>(CamConDevice&, const DeviceInfo&)> makePlan) {
    session.setShowProgress(true);
    const Result<WriteReport> report = runOnCamCon<WriteReport>(
        session, title, [makePlan](CamConDevice& device, JobContext& job) -> Result<WriteReport> {
            const Result<DeviceInfo> info = device.readInfo();
            if (!info) return info.error();
            const Result<WritePlan> plan = makePlan(device, *info);
            if (!plan) return plan.error();
            return usecases::writeItems(device, *info, *plan, usecases::UseCaseProgress::of(job));
        });
    if (!report) return reportError(report.error());
    return printWriteReport(*report);
}

int printWriteReport(const WriteReport& report) {
    QString text;
    for (const usecases::OutcomeLine& line : report.lines()) text += line.text + QLatin1Char('\n');
    text += report.summary() + QLatin1Char('\n');
    printOut(text);
    if (report.complete()) return ExitOk;
    const Error error = report.firstError();
    printError(QStringLiteral("not everything was written: %1").arg(report.summary()));
    return exitCodeFor(error.kind == ErrorKind::None ? ErrorKind::Communication : error.kind);
}

}  // namespace cambench::cli
