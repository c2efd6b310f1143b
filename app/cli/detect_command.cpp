// `detect`: what answers on --port. Each built family's protocols are tried
// at their default line settings (identification queries only) until a
// device identifies itself; the line says which, or everything tried.
#include "cli_output.h"
#include "commands.h"
#include "exit_codes.h"

#include "comm/usecases/detect_device.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace cambench::cli {

namespace {

QJsonObject attemptJson(const usecases::DetectAttempt& attempt) {
    QJsonObject entry{{QStringLiteral("family"), attempt.familyId},
                      {QStringLiteral("protocol"), attempt.protocolId},
                      {QStringLiteral("baud"), attempt.serial.baud}};
    if (!attempt.found.isEmpty())
        entry.insert(QStringLiteral("found"), attempt.found);
    else
        entry.insert(QStringLiteral("failure"), attempt.failure);
    return entry;
}

}  // namespace

int runDetect(CliSession& session, CommandArgs& args) {
    const bool json = args.takeFlag(QStringLiteral("--json"));
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const GlobalOptions& options = session.options();
    // The protocol options given on the command line (a device number, a
    // PC number) are tried with each protocol that takes them.
    const usecases::DetectSettings settings = [&options](const comm::ProtocolInfo& protocol) {
        return comm::ProtocolSettingsPtr(
            comm::settingsWith(protocol, options.protocolValues, options.timeoutMs));
    };
    const Result<usecases::DetectResult> result = session.runUnconnected<usecases::DetectResult>(
        QStringLiteral("detect"),
        [&](comm::JobContext& job) { return usecases::detectDevice(options.port, job, settings); });
    if (!result) return reportError(result.error());
    const usecases::DetectAttempt* found = result->found();
    if (json) {
        QJsonArray attempts;
        for (const usecases::DetectAttempt& attempt : result->attempts)
            attempts << attemptJson(attempt);
        QJsonObject root{{QStringLiteral("port"), result->port},
                         {QStringLiteral("attempts"), attempts}};
        if (found) root.insert(QStringLiteral("found"), attemptJson(*found));
        printOut(QString::fromUtf8(QJsonDocument(root).toJson(QJsonDocument::Indented)));
    } else if (found) {
        printOut(QStringLiteral("%1: %2\n").arg(found->familyId, usecases::attemptLine(*found)));
    } else {
        QStringList tried;
        for (const usecases::DetectAttempt& attempt : result->attempts)
            tried
                << QStringLiteral("  %1: %2").arg(attempt.familyId, usecases::attemptLine(attempt));
        printError(QStringLiteral("nothing answered on %1%2; tried:\n%3\nCheck the cable, the "
                                  "device's power and its interface settings.")
                       .arg(result->port,
                            result->cancelled ? QStringLiteral(" (cancelled)") : QString(),
                            tried.join(QLatin1Char('\n'))));
    }
    return found ? ExitOk : ExitCommunication;
}

}  // namespace cambench::cli
