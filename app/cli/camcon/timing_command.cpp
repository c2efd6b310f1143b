// timing --program P --speed V: where each output's cams switch electrically
// at that speed (dead times act ahead of the programmed positions), the
// shortest time an output is on, and the speed above which its picture
// breaks. From the device, or from a project file with --project.
#include "app/cli/camcon/camcon_commands.h"
#include "app/cli/cli_output.h"
#include "app/cli/exit_codes.h"

#include "comm/camcon/usecases/program_read.h"
#include "model/camcon/cam_timing.h"
#include "model/camcon/project_file.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace cambench::cli {

namespace {

using comm::CamConDevice;
using comm::JobContext;

constexpr int kMaxProgramNumber = 32767;  // as cams read

// What the arithmetic needs of a device or a project.
struct TimingInput {
    CamProgram program;
    DeadTimeModes deadTimes;  // every output with cams; plain dead times as mode Normal
    Axis axis;
    bool axisKnown = true;
    int outputs = 0;
    MinimumPulses minimumPulses;  // the project's, when --min-pulse is not given
};

Result<TimingInput> fromProject(const QString& path, int number) {
    const Result<Project> project = loadProject(path);
    if (!project) return project.error();
    TimingInput input;
    bool found = false;
    for (const CamProgram& program : project->programs) {
        if (program.number != number) continue;
        input.program = program;
        found = true;
    }
    if (!found)
        return Error::invalidData(
            QStringLiteral("%1 holds no program %2 (not read or not there); choose another "
                           "--program")
                .arg(path)
                .arg(number));
    input.deadTimes = deadTimesAsModes(project->deadTimes, project->deadTimeModes);
    input.minimumPulses = project->minimumPulses;
    input.outputs = project->device.outputs;
    input.axis = {project->device.minPosition, project->device.maxPosition,
                  isRotaryAxis(project->settings)};
    return input;
}

Result<TimingInput> fromDevice(CliSession& session, int number) {
    session.setShowProgress(true);
    return runOnCamCon<TimingInput>(
        session, QStringLiteral("timing"),
        [number](CamConDevice& device, JobContext& job) -> Result<TimingInput> {
            TimingInput input;
            Result<usecases::ProgramRead> fetched = usecases::readIdentityAndProgram(
                device, number, usecases::UseCaseProgress::of(job));
            if (!fetched) return fetched.error();
            const DeviceInfo identity = fetched->device;
            input.program = std::move(fetched->program);
            DeadTimeModes modes;
            if (device.has(comm::CamConCapability::DeadTimeModes)) {
                Result<DeadTimeModes> read = device.readDeadTimeModes(identity.deadTimeOutputs);
                if (!read) return read.error();
                modes = *read;
            }
            DeadTimes plain;
            if (modes.isEmpty()) {
                Result<DeadTimes> read = device.readDeadTimes(identity.deadTimeOutputs);
                if (!read) return read.error();
                plain = *read;
            }
            input.deadTimes = deadTimesAsModes(plain, modes);
            input.axis = {identity.minPosition, identity.maxPosition, true};
            input.outputs = identity.outputs;
            const Result<QVariant> axisType = device.readSetting(QStringLiteral("axisType"));
            if (axisType)
                input.axis.rotary = axisType->toLongLong() == 0;
            else
                input.axisKnown = false;
            return input;
        });
}

QString number(double value, int decimals = 1) {
    return QString::number(value, 'f', decimals);
}

QJsonObject problemJson(int output, const TimingProblem& problem, const Axis& axis) {
    static const char* const kinds[] = {"vanishes", "merges", "shortPulse", "shiftOverCycle"};
    QJsonObject json{{QStringLiteral("kind"), QLatin1String(kinds[int(problem.kind)])},
                     {QStringLiteral("cam"), problem.cam},
                     {QStringLiteral("fromSpeed"), fromPositionsPerSecond(problem.fromSpeed, axis)},
                     {QStringLiteral("text"), describeProblem(output, problem, axis)}};
    if (problem.nextCam > 0) json.insert(QStringLiteral("nextCam"), problem.nextCam);
    return json;
}

}  // namespace

int runTiming(CliSession& session, CommandArgs& args) {
    const bool json = args.takeFlag(QStringLiteral("--json"));
    const Result<int> program =
        args.takeIntOption(QStringLiteral("--program"), -1, 0, kMaxProgramNumber);
    if (!program) return reportError(program.error());
    const Result<QString> speedText = args.takeOption(QStringLiteral("--speed"));
    if (!speedText) return reportError(speedText.error());
    const Result<QString> pulseText = args.takeOption(QStringLiteral("--min-pulse"));
    if (!pulseText) return reportError(pulseText.error());
    const Result<QString> axisText = args.takeOption(QStringLiteral("--axis"));
    if (!axisText) return reportError(axisText.error());
    const Result<QString> projectPath = args.takeOption(QStringLiteral("--project"));
    if (!projectPath) return reportError(projectPath.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    if (*program < 0 || speedText->isEmpty())
        return reportError(Error::usage(QStringLiteral("timing needs --program P and --speed V")));
    bool ok = false;
    // A decimal point, never the locale's comma: scripts give "412.5".
    const double speed = speedText->toDouble(&ok);
    if (!ok || speed < 0)
        return reportError(Error::usage(
            QStringLiteral("--speed must be a number of 0 or more, not \"%1\"").arg(*speedText)));
    if (!axisText->isEmpty() && *axisText != QLatin1String("rotary") &&
        *axisText != QLatin1String("linear"))
        return reportError(Error::usage(
            QStringLiteral("--axis must be rotary or linear, not \"%1\"").arg(*axisText)));

    const Result<TimingInput> read = projectPath->isEmpty() ? fromDevice(session, *program)
                                                            : fromProject(*projectPath, *program);
    if (!read) return reportError(read.error());
    TimingInput input = *read;
    if (!pulseText->isEmpty()) {
        const Result<MinimumPulses> pulses = parseMinimumPulses(*pulseText, input.outputs);
        if (!pulses) return reportError(pulses.error());
        input.minimumPulses = *pulses;
    }
    if (!axisText->isEmpty()) {
        input.axis.rotary = *axisText == QLatin1String("rotary");
        input.axisKnown = true;
    }
    if (!input.axisKnown)
        printError(
            QStringLiteral("note: the device did not say whether its axis is rotary or "
                           "linear; taken as rotary (give --axis linear if it is not)"));
    const Axis& axis = input.axis;
    const double v = toPositionsPerSecond(speed, axis);
    const QString unit = speedUnit(axis);

    QJsonArray outputs;
    QString text = QStringLiteral("program %1 at %2 %3 (%4 pos/s), axis %5..%6 %7\n")
                       .arg(*program)
                       .arg(number(speed, speed >= 100 ? 0 : 1), unit, number(v))
                       .arg(axis.min)
                       .arg(axis.max)
                       .arg(axis.rotary ? QStringLiteral("rotary") : QStringLiteral("linear"));
    QStringList warnings;
    for (const OutputTiming& timing :
         timeProgram(input.program, input.deadTimes, v, axis, input.minimumPulses)) {
        QString line = QStringLiteral("output %1: shift %2 pos")
                           .arg(timing.output)
                           .arg(number(timing.shiftOn));
        if (!qFuzzyCompare(timing.shiftOn + 1, timing.shiftOff + 1))
            line = QStringLiteral("output %1: shift on %2 pos, off %3 pos")
                       .arg(timing.output)
                       .arg(number(timing.shiftOn), number(timing.shiftOff));
        line += QStringLiteral(" (dead time %1 ms").arg(number(timing.onDeadTimeMs));
        if (timing.offDeadTimeMs != timing.onDeadTimeMs)
            line += QStringLiteral(" on, %1 ms off").arg(number(timing.offDeadTimeMs));
        line += QLatin1Char(')');
        if (const qint32 pulse = input.minimumPulses.value(timing.output); pulse > 0)
            line += QStringLiteral(", minimum pulse %1 ms").arg(number(pulse / 10.0));
        line += timing.shortestDurationMs
                    ? QStringLiteral(", shortest cam %1 ms").arg(number(*timing.shortestDurationMs))
                    : QStringLiteral(", standing still");
        line += timing.firstLimit
                    ? QStringLiteral(", limit %1")
                          .arg(describeProblem(timing.output, *timing.firstLimit, axis)
                                   .section(QStringLiteral(": "), 1))
                    : QStringLiteral(", no limit");
        text += line + QLatin1Char('\n');
        for (const TimingProblem& problem : timing.problems)
            warnings << QStringLiteral("warning: %1 (at %2 %3)")
                            .arg(describeProblem(timing.output, problem, axis),
                                 number(speed, speed >= 100 ? 0 : 1), unit);

        QJsonArray cams;
        for (const TimedCam& cam : timing.cams) {
            QJsonObject c{{QStringLiteral("cam"), cam.number},
                          {QStringLiteral("programmedOn"), cam.programmed.on},
                          {QStringLiteral("programmedOff"), cam.programmed.off},
                          {QStringLiteral("on"), cam.on},
                          {QStringLiteral("off"), cam.off},
                          {QStringLiteral("length"), cam.length}};
            if (cam.durationMs) c.insert(QStringLiteral("durationMs"), *cam.durationMs);
            cams.append(c);
        }
        QJsonArray problems;
        for (const TimingProblem& problem : timing.problems)
            problems.append(problemJson(timing.output, problem, axis));
        QJsonObject entry{{QStringLiteral("output"), timing.output},
                          {QStringLiteral("onDeadTimeMs"), timing.onDeadTimeMs},
                          {QStringLiteral("offDeadTimeMs"), timing.offDeadTimeMs},
                          {QStringLiteral("shiftOn"), timing.shiftOn},
                          {QStringLiteral("shiftOff"), timing.shiftOff},
                          {QStringLiteral("cams"), cams},
                          {QStringLiteral("problems"), problems}};
        if (input.minimumPulses.value(timing.output) > 0)
            entry.insert(QStringLiteral("minPulseMs"),
                         input.minimumPulses.value(timing.output) / 10.0);
        if (timing.shortestDurationMs)
            entry.insert(QStringLiteral("shortestCamMs"), *timing.shortestDurationMs);
        if (timing.firstLimit)
            entry.insert(QStringLiteral("limit"),
                         problemJson(timing.output, *timing.firstLimit, axis));
        outputs.append(entry);
    }
    if (json) {
        return printJson(QJsonDocument(QJsonObject{
            {QStringLiteral("program"), *program},
            {QStringLiteral("speed"), speed},
            {QStringLiteral("speedUnit"), unit},
            {QStringLiteral("positionsPerSecond"), v},
            {QStringLiteral("axis"), QJsonObject{{QStringLiteral("min"), axis.min},
                                                 {QStringLiteral("max"), axis.max},
                                                 {QStringLiteral("rotary"), axis.rotary}}},
            {QStringLiteral("outputs"), outputs}}));
    }
    printOut(text);
    for (const QString& warning : warnings) printOut(warning + QLatin1Char('\n'));
    return ExitOk;
}

}  // namespace cambench::cli
