// deadtimes read/write, names read/write: per-output (and per-program) tables as CSV.
#include "app/cli/camcon/camcon_commands.h"
#include "app/cli/cli_output.h"
#include "app/cli/exit_codes.h"
#include "write_output.h"

#include "model/camcon/csv_io.h"

namespace cambench::cli {

namespace {

using comm::CamConDevice;
using comm::JobContext;

// `write FILE`: loads the file (its format is checked before any device
// work) and writes it through the one write path, which checks it against
// the device first and reports every item.
template <class T>
int writeTable(CliSession& session, CommandArgs& args, const QString& title,
               Result<T> (*load)(const QString&), usecases::WritePlan (*toPlan)(const T&)) {
    const Result<QString> path = args.takeRequiredPositional(QStringLiteral("a CSV FILE"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<T> table = load(*path);
    if (!table) return reportError(table.error());
    const usecases::WritePlan plan = toPlan(*table);
    return runWritePlan(session, title, plan);
}

// On the table interface with its mode columns (which hold the plain
// dead time as the mode normal's), elsewhere the plain dead times.
Result<DeadTimeTable> readAllDeadTimes(CamConDevice& client, JobContext&) {
    const Result<DeviceInfo> info = client.readInfo();
    if (!info) return info.error();
    DeadTimeTable table;
    if (client.has(comm::CamConCapability::DeadTimeModes)) {
        Result<DeadTimeModes> modes = client.readDeadTimeModes(info->deadTimeOutputs);
        if (!modes) return modes.error();
        table.modes = *modes;
        return table;
    }
    Result<DeadTimes> deadTimes = client.readDeadTimes(info->deadTimeOutputs);
    if (!deadTimes) return deadTimes.error();
    table.deadTimes = *deadTimes;
    return table;
}

QByteArray deadTimeTableToCsv(const DeadTimeTable& table) {
    return table.modes.isEmpty() ? deadTimesToCsv(table.deadTimes)
                                 : deadTimeModesToCsv(table.modes);
}

usecases::WritePlan deadTimesPlan(const DeadTimeTable& table) {
    usecases::WritePlan plan;
    for (auto it = table.deadTimes.cbegin(); it != table.deadTimes.cend(); ++it)
        plan.deadTimes << usecases::DeadTimeWrite{it.key(), *it, {}};
    for (auto it = table.modes.cbegin(); it != table.modes.cend(); ++it)
        plan.deadTimeModes << usecases::DeadTimeModeWrite{it.key(), *it, {}};
    return plan;
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

usecases::WritePlan namesPlan(const Names& names) {
    usecases::WritePlan plan;
    for (auto it = names.outputs.cbegin(); it != names.outputs.cend(); ++it)
        plan.outputNames << usecases::NameWrite{it.key(), *it, {}};
    for (auto it = names.programs.cbegin(); it != names.programs.cend(); ++it)
        plan.programNames << usecases::NameWrite{it.key(), *it, {}};
    return plan;
}

}  // namespace

int runDeadTimes(CliSession& session, CommandArgs& args) {
    const Result<QString> verb = takeVerb(args, {QStringLiteral("read"), QStringLiteral("write")});
    if (!verb) return reportError(verb.error());
    if (*verb == QLatin1String("read")) {
        return readToOutput<DeadTimeTable>(session, args, QStringLiteral("deadtimes read"),
                                           readAllDeadTimes, deadTimeTableToCsv);
    }
    return writeTable<DeadTimeTable>(session, args, QStringLiteral("deadtimes write"),
                                     loadDeadTimeTableCsv, deadTimesPlan);
}

int runNames(CliSession& session, CommandArgs& args) {
    const Result<QString> verb = takeVerb(args, {QStringLiteral("read"), QStringLiteral("write")});
    if (!verb) return reportError(verb.error());
    if (*verb == QLatin1String("read")) {
        session.setShowProgress(true);
        return readToOutput<Names>(session, args, QStringLiteral("names read"), readAllNames,
                                   namesToCsv);
    }
    return writeTable<Names>(session, args, QStringLiteral("names write"), loadNamesCsv, namesPlan);
}

}  // namespace cambench::cli
