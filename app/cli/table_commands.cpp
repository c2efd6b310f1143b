// deadtimes read/write, names read/write: per-output (and per-program) tables as CSV.
#include "cli_output.h"
#include "commands.h"
#include "exit_codes.h"

#include "model/camcon/csv_io.h"
#include "model/camcon/data_validation.h"

namespace cambench::cli {

namespace {

using comm::CamConDevice;
using comm::JobContext;

// `read [-o FILE]`: runs `read` and writes what `toCsv` makes of it.
template <class T>
int readTable(CliSession& session, CommandArgs& args, const QString& title,
              CliSession::Work<T> read, QByteArray (*toCsv)(const T&)) {
    const Result<QString> path =
        args.takeOption(QStringLiteral("--output-file"), QStringLiteral("-o"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<T> table = session.run<T>(title, std::move(read));
    if (!table) return reportError(table.error());
    const Status written = writeOutput(*path, toCsv(*table));
    return written ? ExitOk : reportError(written.error());
}

// `write FILE`: loads the file, then in one job checks it against the
// device (`validate`) and writes it (`write`), or writes nothing.
template <class T>
int writeTable(CliSession& session, CommandArgs& args, const QString& title,
               Result<T> (*load)(const QString&),
               QStringList (*validate)(const T&, const DeviceInfo&),
               std::function<Status(CamConDevice&, const T&)> write) {
    const Result<QString> path = args.takeRequiredPositional(QStringLiteral("a CSV FILE"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<T> table = load(*path);
    if (!table) return reportError(table.error());
    const QString file = *path;
    const T data = *table;
    const Status written = session.run<Done>(
        title, [file, data, validate, write](CamConDevice& client, JobContext&) -> Status {
            const Result<DeviceInfo> info = client.readInfo();
            if (!info) return info.error();
            const QStringList problems = validate(data, *info);
            if (!problems.isEmpty()) return invalidFileError(file, problems);
            return write(client, data);
        });
    return written ? ExitOk : reportError(written.error());
}

Result<DeadTimes> readAllDeadTimes(CamConDevice& client, JobContext&) {
    const Result<DeviceInfo> info = client.readInfo();
    if (!info) return info.error();
    return client.readDeadTimes(info->deadTimeOutputs);
}

Status writeAllDeadTimes(CamConDevice& client, const DeadTimes& deadTimes) {
    for (auto it = deadTimes.begin(); it != deadTimes.end(); ++it) {
        if (const Status ok = client.writeDeadTime(it.key(), it.value()); !ok) return ok;
    }
    return success();
}

Result<Names> readAllNames(CamConDevice& client, JobContext& job) {
    const Result<DeviceInfo> info = client.readInfo();
    if (!info) return info.error();
    Names names;
    const int total = info->outputs + info->programs;
    for (int output = 1; output <= info->outputs; ++output) {
        job.progress(output - 1, total, QStringLiteral("reading names"));
        const Result<QString> name = client.readOutputName(output);
        if (!name) return name.error();
        names.outputs.insert(output, *name);
    }
    for (int program = 0; program < info->programs; ++program) {
        job.progress(info->outputs + program, total, QStringLiteral("reading names"));
        const Result<QString> name = client.readProgramName(program);
        if (!name) return name.error();
        names.programs.insert(program, *name);
    }
    return names;
}

Status writeAllNames(CamConDevice& client, const Names& names) {
    for (auto it = names.outputs.begin(); it != names.outputs.end(); ++it) {
        if (const Status ok = client.writeOutputName(it.key(), it.value()); !ok) return ok;
    }
    for (auto it = names.programs.begin(); it != names.programs.end(); ++it) {
        if (const Status ok = client.writeProgramName(it.key(), it.value()); !ok) return ok;
    }
    return success();
}

}  // namespace

int runDeadTimes(CliSession& session, CommandArgs& args) {
    const Result<QString> verb = takeVerb(args, {QStringLiteral("read"), QStringLiteral("write")});
    if (!verb) return reportError(verb.error());
    if (*verb == QLatin1String("read")) {
        return readTable<DeadTimes>(session, args, QStringLiteral("deadtimes read"),
                                    readAllDeadTimes, deadTimesToCsv);
    }
    return writeTable<DeadTimes>(session, args, QStringLiteral("deadtimes write"), loadDeadTimesCsv,
                                 validateDeadTimes, writeAllDeadTimes);
}

int runNames(CliSession& session, CommandArgs& args) {
    const Result<QString> verb = takeVerb(args, {QStringLiteral("read"), QStringLiteral("write")});
    if (!verb) return reportError(verb.error());
    if (*verb == QLatin1String("read")) {
        session.setShowProgress(true);
        return readTable<Names>(session, args, QStringLiteral("names read"), readAllNames,
                                namesToCsv);
    }
    return writeTable<Names>(session, args, QStringLiteral("names write"), loadNamesCsv,
                             validateNames, writeAllNames);
}

}  // namespace cambench::cli
