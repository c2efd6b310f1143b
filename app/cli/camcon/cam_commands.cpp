// cams read / cams write
#include "app/cli/camcon/camcon_commands.h"
#include "app/cli/cli_output.h"
#include "app/cli/exit_codes.h"
#include "write_output.h"

#include "comm/camcon/usecases/program_read.h"
#include "model/camcon/csv_io.h"

namespace cambench::cli {

namespace {

using comm::CamConDevice;
using comm::JobContext;

constexpr int kMaxProgramNumber = 32767;  // 4 hex digits, manual 5.2.1.1

int readCams(CliSession& session, CommandArgs& args) {
    const Result<int> program =
        args.takeIntOption(QStringLiteral("--program"), -1, 0, kMaxProgramNumber);
    if (!program) return reportError(program.error());
    const Result<int> output = args.takeIntOption(QStringLiteral("--output"), 0, 1, 200);
    if (!output) return reportError(output.error());
    const Result<QString> path =
        args.takeOption(QStringLiteral("--output-file"), QStringLiteral("-o"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    if (*program < 0)
        return reportError(Error::usage(QStringLiteral("cams read needs --program P")));

    session.setShowProgress(true);
    const int p = *program;
    const int o = *output;
    const Result<Tracks> tracks = runOnCamCon<Tracks>(
        session, QStringLiteral("cams read"),
        [p, o](CamConDevice& client, JobContext& job) -> Result<Tracks> {
            const Result<DeviceInfo> info = client.readInfo();
            if (!info) return info.error();
            if (const Status ok = usecases::checkProgramNumber(p, *info); !ok) return ok.error();
            if (o > 0) {
                if (o > info->outputs) {
                    return Error::invalidData(
                        QStringLiteral("output %1 does not exist on the device "
                                       "(outputs 1..%2); choose another --output")
                            .arg(o)
                            .arg(info->outputs));
                }
                Result<Track> track = client.readTrack(p, o);
                if (!track) return track.error();
                Tracks one;
                if (!track->cams.isEmpty()) one.insert(o, std::move(track).value());
                return one;
            }
            const Result<CamProgram> read =
                usecases::readProgram(client, *info, p, usecases::UseCaseProgress::of(job));
            if (!read) return read.error();
            return read->tracks;
        });
    if (!tracks) return reportError(tracks.error());
    const Status written = writeOutput(*path, camsToCsv(*tracks));
    return written ? ExitOk : reportError(written.error());
}

int writeCams(CliSession& session, CommandArgs& args) {
    const Result<int> program =
        args.takeIntOption(QStringLiteral("--program"), -1, 0, kMaxProgramNumber);
    if (!program) return reportError(program.error());
    const Result<QString> path = args.takeRequiredPositional(QStringLiteral("a CSV FILE"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    if (*program < 0)
        return reportError(Error::usage(QStringLiteral("cams write needs --program P")));
    // The file's format is checked before any device work.
    const Result<Tracks> tracks = loadCamsCsv(*path);
    if (!tracks) return reportError(tracks.error());
    // Exactly the tracks the file lists: each becomes what the file says.
    // The write path checks them against the device before the first byte.
    usecases::WritePlan plan;
    for (const Track& track : *tracks) plan.tracks << usecases::TrackWrite{*program, track, {}};
    return runWritePlan(session, QStringLiteral("cams write"), plan);
}

}  // namespace

int runCams(CliSession& session, CommandArgs& args) {
    const Result<QString> verb = takeVerb(args, {QStringLiteral("read"), QStringLiteral("write")});
    if (!verb) return reportError(verb.error());
    return *verb == QLatin1String("read") ? readCams(session, args) : writeCams(session, args);
}

}  // namespace cambench::cli
