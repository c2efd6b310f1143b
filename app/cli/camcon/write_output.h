#pragma once

#include "app/cli/camcon/camcon_commands.h"
#include "app/cli/cli_options.h"
#include "app/cli/cli_output.h"
#include "app/cli/cli_session.h"
#include "app/cli/exit_codes.h"

#include "comm/camcon/usecases/write_items.h"

namespace cambench::cli {

// Runs `plan` (made by `makePlan` inside the job, after the device's
// identity was read) through the one write path and prints the outcome of
// every item, then the summary. Exit 0 only when every item was written or
// unchanged; a refused plan exits 4 before anything was sent.
int runWritePlan(
    CliSession& session, const QString& title,
    std::function<Result<usecases::WritePlan>(comm::CamConDevice&, const DeviceInfo&)> makePlan);

// The same for a plan made before any device work (from a file).
int runWritePlan(CliSession& session, const QString& title, const usecases::WritePlan& plan);

// --communication-settings KEYS of a write from a file (issue 39): the
// communication settings (protocol, deviceNumber) the person names, to be
// written; empty when not given. Names them on stderr with what the next
// connection will need, before anything is sent. A key that is no
// communication setting is a usage error that lists them.
Result<QStringList> takeCommunicationSettings(CommandArgs& args);

// `read [-o FILE]` of a section: runs `read` and writes `toText` of what it
// returns to FILE or stdout.
template <class T>
int readToOutput(CliSession& session, CommandArgs& args, const QString& title, CamConWork<T> read,
                 std::function<QByteArray(const T&)> toText) {
    const Result<QString> path =
        args.takeOption(QStringLiteral("--output-file"), QStringLiteral("-o"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<T> value = runOnCamCon<T>(session, title, std::move(read));
    if (!value) return reportError(value.error());
    const Status written = writeOutput(*path, toText(*value));
    return written ? ExitOk : reportError(written.error());
}

// Prints the report: one line per item on stdout, the summary last; when
// not everything was written the summary also goes to stderr. Returns the
// exit code.
int printWriteReport(const usecases::WriteReport& report);

}  // namespace cambench::cli
