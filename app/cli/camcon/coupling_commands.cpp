// `short ...`: the S7-CP340 coupling's short commands 0x01..0x07 on the
// table interface (issue 12, point 5), as the PLC's function block sends
// them, so that a technician can tell whether the CamCon or the PLC program
// is at fault. Outputs count from 1 as everywhere; programs from 0 as on the
// device. Every write is checked with its query before and after
// (comm/usecases/short_coupling.h) and reported as one item.
#include "app/cli/camcon/camcon_commands.h"
#include "app/cli/camcon/cli_format.h"
#include "app/cli/cli_output.h"
#include "app/cli/exit_codes.h"
#include "write_output.h"

#include "comm/camcon/table/short_client.h"
#include "comm/camcon/usecases/program_read.h"
#include "comm/camcon/usecases/short_coupling.h"
#include "model/camcon/cam_validation.h"
#include "model/camcon/csv_io.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace cambench::cli {

namespace {

using comm::CamConDevice;
using comm::table::ShortClient;
using comm::table::ShortStatus;

// Runs `work` with the device's short commands.
template <class T>
Result<T> runShort(CliSession& session, const QString& title,
                   std::function<Result<T>(ShortClient&, CamConDevice&)> work) {
    return runOnCamCon<T>(session, title, comm::table::withShortCommands<T>(std::move(work)));
}

QString statusText(const ShortStatus& status) {
    return keyValueLines({
        {QStringLiteral("actualValue"), status.actualValue},
        {QStringLiteral("speed"), status.speed},
        {QStringLiteral("program"), status.program},
        {QStringLiteral("deviceStatus"), status.deviceStatus},
        {QStringLiteral("deviceStatusText"),
         comm::table::shortDeviceStatusText(status.deviceStatus)},
        {QStringLiteral("outputCount"), status.outputCount},
        {QStringLiteral("outputsOn"), numberList(onNumbers(status.outputs))},
    });
}

QJsonObject statusJson(const ShortStatus& status) {
    return {{QStringLiteral("actualValue"), status.actualValue},
            {QStringLiteral("speed"), status.speed},
            {QStringLiteral("program"), status.program},
            {QStringLiteral("deviceStatus"), status.deviceStatus},
            {QStringLiteral("deviceStatusText"),
             comm::table::shortDeviceStatusText(status.deviceStatus)},
            {QStringLiteral("outputCount"), status.outputCount},
            {QStringLiteral("outputsOn"), jsonNumbers(onNumbers(status.outputs))}};
}

int runStatusQuery(CliSession& session, CommandArgs& args) {
    const bool json = args.takeFlag(QStringLiteral("--json"));
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<ShortStatus> status =
        runShort<ShortStatus>(session, QStringLiteral("short status"),
                              [](ShortClient& client, CamConDevice&) { return client.status(); });
    if (!status) return reportError(status.error());
    if (json) return printJson(QJsonDocument(statusJson(*status)));
    printOut(statusText(*status));
    return ExitOk;
}

// What a write did, established by its query before and after: one line.
int printOutcome(const Result<usecases::OutcomeLine>& outcome) {
    if (!outcome) return reportError(outcome.error());
    printOut(outcome->text + u'\n');
    const bool ok = outcome->state == usecases::WriteState::Written ||
                    outcome->state == usecases::WriteState::Unchanged;
    if (ok) return ExitOk;
    return outcome->error.kind == ErrorKind::None ? ExitDevice : exitCodeFor(outcome->error.kind);
}

int runResetErrors(CliSession& session, CommandArgs& args) {
    if (const Status done = args.finish(); !done) return reportError(done.error());
    return printOutcome(runShort<usecases::OutcomeLine>(
        session, QStringLiteral("short reset-errors"),
        [](ShortClient& client, CamConDevice&) -> Result<usecases::OutcomeLine> {
            return usecases::shortResetErrors(client);
        }));
}

Status checkOutput(int output, const DeviceInfo& info) {
    if (output <= info.outputs) return success();
    return Error::invalidData(
        QStringLiteral("output %1 does not exist: this device has outputs 1..%2")
            .arg(output)
            .arg(info.outputs));
}

// The device's identity, once `output` is known to exist on it.
Result<DeviceInfo> infoWithOutput(CamConDevice& device, int output) {
    Result<DeviceInfo> info = device.readInfo();
    if (!info) return info.error();
    if (const Status fits = checkOutput(output, *info); !fits) return fits.error();
    return info;
}

int runProgramChange(CliSession& session, CommandArgs& args) {
    const Result<QString> text = args.takeRequiredPositional(QStringLiteral("a program number"));
    if (!text) return reportError(text.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    bool ok = false;
    const int program = text->toInt(&ok);
    if (!ok || program < 0)
        return reportError(Error::usage(
            QStringLiteral("short program needs a program number 0 or more, not \"%1\"")
                .arg(*text)));
    return printOutcome(runShort<usecases::OutcomeLine>(
        session, QStringLiteral("short program"),
        [program](ShortClient& client, CamConDevice& device) -> Result<usecases::OutcomeLine> {
            const Result<DeviceInfo> info = device.readInfo();
            if (!info) return info.error();
            if (const Status fits = usecases::checkProgramNumber(program, *info); !fits)
                return fits.error();
            return usecases::shortChangeProgram(client, program);
        }));
}

// Output O (from 1) on the command line, checked against the device.
Result<int> takeOutput(CommandArgs& args) {
    const Result<QString> text = args.takeRequiredPositional(QStringLiteral("an output number"));
    if (!text) return text.error();
    bool ok = false;
    const int output = text->toInt(&ok);
    if (!ok || output < 1)
        return Error::usage(QStringLiteral("outputs count from 1, not \"%1\"").arg(*text));
    return output;
}

int runTrackRead(CliSession& session, CommandArgs& args) {
    const Result<int> output = takeOutput(args);
    if (!output) return reportError(output.error());
    // -1: the active program, as the status query reports it.
    const Result<int> program = args.takeIntOption(QStringLiteral("--program"), -1, 0, 65535);
    if (!program) return reportError(program.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<Track> track = runShort<Track>(
        session, QStringLiteral("short track read"),
        [output = *output, program = *program](ShortClient& client,
                                               CamConDevice& device) -> Result<Track> {
            const Result<DeviceInfo> info = infoWithOutput(device, output);
            if (!info) return info.error();
            int chosen = program;
            if (chosen < 0) {
                const Result<ShortStatus> status = client.status();
                if (!status) return status.error();
                chosen = status->program;
            }
            if (const Status fits = usecases::checkProgramNumber(chosen, *info); !fits)
                return fits.error();
            return client.readTrack(chosen, output);
        });
    if (!track) return reportError(track.error());
    printOut(QString::fromUtf8(camsToCsv(Tracks{{*output, *track}})));
    return ExitOk;
}

int runTrackWrite(CliSession& session, CommandArgs& args) {
    const Result<int> output = takeOutput(args);
    if (!output) return reportError(output.error());
    const Result<QString> path = args.takeRequiredPositional(QStringLiteral("a CSV FILE"));
    if (!path) return reportError(path.error());
    // No default: the short command writes into a program that may be running.
    const Result<int> program = args.takeIntOption(QStringLiteral("--program"), -1, 0, 65535);
    if (!program) return reportError(program.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    if (*program < 0) {
        return reportError(Error::usage(QStringLiteral(
            "short track write needs --program P: the cams go into that program at once, "
            "even while it runs")));
    }
    const Result<Tracks> tracks = loadCamsCsv(*path);
    if (!tracks) return reportError(tracks.error());
    if (tracks->size() > 1 || (!tracks->isEmpty() && !tracks->contains(*output))) {
        return reportError(Error::invalidData(
            QStringLiteral("%1 holds cams of outputs %2; short track write %3 takes a file with "
                           "the cams of output %3 only")
                .arg(*path,
                     [&] {
                         QStringList outputs;
                         for (int o : tracks->keys()) outputs.append(QString::number(o));
                         return outputs.join(u',');
                     }())
                .arg(*output)));
    }
    Track wanted = tracks->value(*output);
    wanted.output = *output;
    return printOutcome(runShort<usecases::OutcomeLine>(
        session, QStringLiteral("short track write"),
        [wanted, program = *program](ShortClient& client,
                                     CamConDevice& device) -> Result<usecases::OutcomeLine> {
            const Result<DeviceInfo> info = infoWithOutput(device, wanted.output);
            if (!info) return info.error();
            if (const Status fits = usecases::checkProgramNumber(program, *info); !fits)
                return fits.error();
            const Result<QVariant> axisType = device.readSetting(QStringLiteral("axisType"));
            if (!axisType) return axisType.error();
            const bool rotary = axisType->toLongLong() == 0;
            const QList<CamProblem> problems = validateTrack(wanted, program, *info, rotary);
            if (!problems.isEmpty()) {
                return Error::invalidData(
                    QStringLiteral("nothing was written: %1").arg(problems.first().message));
            }
            return usecases::shortWriteTrack(client, program, wanted);
        }));
}

int runDeadTimeRead(CliSession& session, CommandArgs& args) {
    const Result<int> output = takeOutput(args);
    if (!output) return reportError(output.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<int> deadTime =
        runShort<int>(session, QStringLiteral("short deadtime read"),
                      [output = *output](ShortClient& client, CamConDevice& device) -> Result<int> {
                          const Result<DeviceInfo> info = infoWithOutput(device, output);
                          if (!info) return info.error();
                          return client.readDeadTime(output);
                      });
    if (!deadTime) return reportError(deadTime.error());
    printOut(QString::fromUtf8(deadTimesToCsv(DeadTimes{{*output, *deadTime}})));
    return ExitOk;
}

int runDeadTimeWrite(CliSession& session, CommandArgs& args) {
    const Result<int> output = takeOutput(args);
    if (!output) return reportError(output.error());
    const Result<QString> text =
        args.takeRequiredPositional(QStringLiteral("a dead time in 0.1 ms"));
    if (!text) return reportError(text.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    bool ok = false;
    const int value = text->toInt(&ok);
    if (!ok || value < 0 || value > 0xFFFF) {
        return reportError(Error::usage(
            QStringLiteral("a dead time is a whole number of 0.1 ms, 0..65535, not \"%1\"")
                .arg(*text)));
    }
    return printOutcome(runShort<usecases::OutcomeLine>(
        session, QStringLiteral("short deadtime write"),
        [output = *output, value](ShortClient& client,
                                  CamConDevice& device) -> Result<usecases::OutcomeLine> {
            const Result<DeviceInfo> info = device.readInfo();
            if (!info) return info.error();
            if (output > info->deadTimeOutputs) {
                return Error::invalidData(
                    QStringLiteral("output %1 has no dead time: this device has dead times on "
                                   "outputs 1..%2")
                        .arg(output)
                        .arg(info->deadTimeOutputs));
            }
            return usecases::shortWriteDeadTime(client, output, value);
        }));
}

}  // namespace

int runShortCommands(CliSession& session, CommandArgs& args) {
    const Result<QString> verb = takeVerb(
        args, {QStringLiteral("status"), QStringLiteral("reset-errors"), QStringLiteral("program"),
               QStringLiteral("track"), QStringLiteral("deadtime")});
    if (!verb) return reportError(verb.error());
    if (*verb == QLatin1String("status")) return runStatusQuery(session, args);
    if (*verb == QLatin1String("reset-errors")) return runResetErrors(session, args);
    if (*verb == QLatin1String("program")) return runProgramChange(session, args);
    const Result<QString> direction =
        takeVerb(args, {QStringLiteral("read"), QStringLiteral("write")});
    if (!direction) return reportError(direction.error());
    const bool read = *direction == QLatin1String("read");
    if (*verb == QLatin1String("track"))
        return read ? runTrackRead(session, args) : runTrackWrite(session, args);
    return read ? runDeadTimeRead(session, args) : runDeadTimeWrite(session, args);
}

}  // namespace cambench::cli
