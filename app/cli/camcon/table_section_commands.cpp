// `analogue`, `programming`, `eeprom-lock`: the table interface's sections
// beside the dead-time modes (issue 12, point 2). Reads print what the
// device holds; writes go through the one write path, checked against the
// device first and reported per item. Over a protocol without the section
// the read fails with the reason and a write reports the item "not sent".
#include "app/cli/camcon/camcon_commands.h"
#include "app/cli/camcon/cli_format.h"
#include "app/cli/cli_output.h"
#include "app/cli/exit_codes.h"
#include "write_output.h"

#include "comm/camcon/usecases/value_text.h"
#include "model/camcon/csv_io.h"

#include <algorithm>

namespace cambench::cli {

namespace {

using comm::CamConDevice;
using comm::JobContext;

int runAnalogueRead(CliSession& session, CommandArgs& args) {
    const Result<int> only = args.takeIntOption(QStringLiteral("--output"), 0, 1, kAnalogueOutputs);
    if (!only) return reportError(only.error());
    const int first = *only == 0 ? 1 : *only;
    const int last = *only == 0 ? kAnalogueOutputs : *only;
    return readToOutput<QList<AnalogueCamTrack>>(
        session, args, QStringLiteral("analogue read"),
        [first, last](CamConDevice& device, JobContext& job) -> Result<QList<AnalogueCamTrack>> {
            // Only the outputs the device says it has: it refuses the others' areas.
            const Result<int> count = device.readAnalogueOutputCount();
            if (!count) return count.error();
            if (*count < last && first == last) {
                return Error::invalidData(QStringLiteral("Analogue output %1 does not exist: this "
                                                         "device has %2 analogue outputs.")
                                              .arg(first)
                                              .arg(*count));
            }
            QList<AnalogueCamTrack> tracks;
            for (int output = first; output <= std::min(last, *count); ++output) {
                job.progress(output - first, last - first + 1,
                             QStringLiteral("reading analogue output %1").arg(output));
                Result<AnalogueCamTrack> track = device.readAnalogueCams(output);
                if (!track) return track.error();
                tracks << *track;
            }
            return tracks;
        },
        analogueCamsToCsv);
}

int runAnalogueWrite(CliSession& session, CommandArgs& args) {
    const Result<QString> path = args.takeRequiredPositional(QStringLiteral("a CSV FILE"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<QList<AnalogueCamTrack>> tracks = loadAnalogueCamsCsv(*path);
    if (!tracks) return reportError(tracks.error());
    usecases::WritePlan plan;
    for (const AnalogueCamTrack& track : *tracks)
        plan.analogueCams << usecases::AnalogueCamWrite{track, {}};
    return runWritePlan(session, QStringLiteral("analogue write"), plan);
}

QByteArray programmingText(const ProgrammingProgram& programming) {
    return keyValueLines(
               {
                   {QStringLiteral("program"), programming.program},
                   {QStringLiteral("selectMode"), programmingSelectModeKey(programming.selectMode)},
                   {QStringLiteral("switchValue"), programming.switchValue},
                   {QStringLiteral("text"), usecases::programmingProgramText(programming)},
               })
        .toUtf8();
}

// `programming write PROGRAM [--mode slow|direct|at-value] [--switch-value N]`:
// what is not given stays as the device holds it.
int runProgrammingWrite(CliSession& session, CommandArgs& args) {
    const Result<QString> modeText = args.takeOption(QStringLiteral("--mode"));
    if (!modeText) return reportError(modeText.error());
    const Result<QString> switchText = args.takeOption(QStringLiteral("--switch-value"));
    if (!switchText) return reportError(switchText.error());
    const Result<QString> programText =
        args.takeRequiredPositional(QStringLiteral("a program number"));
    if (!programText) return reportError(programText.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<int> program =
        parseIntArgument(*programText, QStringLiteral("the program"), 0, 9999);
    if (!program) return reportError(program.error());
    const int mode = modeText->isEmpty() ? -1 : programmingSelectModeFromKey(*modeText);
    if (!modeText->isEmpty() && mode < 0) {
        return reportError(Error::usage(
            QStringLiteral("--mode must be slow, direct or at-value, not \"%1\"").arg(*modeText)));
    }
    std::optional<qint32> switchValue;
    if (!switchText->isEmpty()) {
        const Result<int> value =
            parseIntArgument(*switchText, QStringLiteral("--switch-value"),
                             std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
        if (!value) return reportError(value.error());
        switchValue = *value;
    }
    return runWritePlan(
        session, QStringLiteral("programming write"),
        [program = *program, mode, switchValue](CamConDevice& device,
                                                const DeviceInfo&) -> Result<usecases::WritePlan> {
            ProgrammingProgram wanted;
            std::optional<ProgrammingProgram> current;
            if (mode < 0 || !switchValue) {
                // The rest as the device holds it (where it has the section).
                if (device.has(comm::CamConCapability::ProgrammingProgram)) {
                    Result<ProgrammingProgram> read = device.readProgrammingProgram();
                    if (!read) return read.error();
                    current = *read;
                    wanted = *read;
                }
            }
            wanted.program = program;
            if (mode >= 0) wanted.selectMode = mode;
            if (switchValue) wanted.switchValue = *switchValue;
            usecases::WritePlan plan;
            plan.programmingProgram = usecases::ProgrammingProgramWrite{wanted, current};
            return plan;
        });
}

int runEepromLockWrite(CliSession& session, bool locked) {
    usecases::WritePlan plan;
    plan.eepromLock = usecases::EepromLockWrite{locked, {}};
    return runWritePlan(
        session, locked ? QStringLiteral("eeprom-lock lock") : QStringLiteral("eeprom-lock unlock"),
        plan);
}

}  // namespace

int runAnalogue(CliSession& session, CommandArgs& args) {
    const Result<QString> verb = takeVerb(args, {QStringLiteral("read"), QStringLiteral("write")});
    if (!verb) return reportError(verb.error());
    return *verb == QLatin1String("read") ? runAnalogueRead(session, args)
                                          : runAnalogueWrite(session, args);
}

int runProgramming(CliSession& session, CommandArgs& args) {
    const Result<QString> verb = takeVerb(args, {QStringLiteral("read"), QStringLiteral("write")});
    if (!verb) return reportError(verb.error());
    if (*verb == QLatin1String("write")) return runProgrammingWrite(session, args);
    return readToOutput<ProgrammingProgram>(
        session, args, QStringLiteral("programming read"),
        [](CamConDevice& device, JobContext&) { return device.readProgrammingProgram(); },
        programmingText);
}

int runEepromLock(CliSession& session, CommandArgs& args) {
    const Result<QString> verb =
        takeVerb(args, {QStringLiteral("read"), QStringLiteral("lock"), QStringLiteral("unlock")});
    if (!verb) return reportError(verb.error());
    if (*verb != QLatin1String("read")) {
        if (const Status done = args.finish(); !done) return reportError(done.error());
        return runEepromLockWrite(session, *verb == QLatin1String("lock"));
    }
    return readToOutput<bool>(
        session, args, QStringLiteral("eeprom-lock read"),
        [](CamConDevice& device, JobContext&) { return device.readEepromLock(); },
        [](const bool& locked) {
            return keyValueLines({{QStringLiteral("locked"), locked},
                                  {QStringLiteral("text"), usecases::eepromLockText(locked)}})
                .toUtf8();
        });
}

}  // namespace cambench::cli
