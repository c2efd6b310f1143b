#include "write_output.h"

#include "app/cli/cli_output.h"
#include "app/cli/exit_codes.h"

#include "model/camcon/link_settings.h"

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

Result<QStringList> takeCommunicationSettings(CommandArgs& args) {
    const Result<QString> option = args.takeOption(QStringLiteral("--communication-settings"));
    if (!option) return option.error();
    if (option->isEmpty()) return QStringList();
    QStringList keys;
    for (const QString& key : option->split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        if (!isLinkSetting(key.trimmed()))
            return Error::usage(QStringLiteral("--communication-settings takes %1, not \"%2\"")
                                    .arg(linkSettingKeys().join(QLatin1Char(',')), key));
        keys << key.trimmed();
    }
    printError(QStringLiteral("note: %1 will be written last where the file's value differs from "
                              "the device's; the next connection to the device then needs the new "
                              "value (--protocol, --device)")
                   .arg(keys.join(QLatin1String(", "))));
    return keys;
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
