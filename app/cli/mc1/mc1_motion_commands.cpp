// mc run|stop|step|reset, mc flash, mc axis: commands that make the
// controller act. Each goes out once; a lost answer exits 3 with what
// reading back found (Mc1Device says it).
#include "mc1_commands.h"

#include "app/cli/cli_output.h"
#include "app/cli/exit_codes.h"

#include "comm/mc1/mc1_parameters.h"

#include <QJsonObject>

namespace cambench::cli {

namespace {

using comm::JobContext;
using comm::Mc1AxisCommand;
using comm::Mc1AxisState;
using comm::Mc1Device;
using comm::Mc1ProgramCommand;

QJsonObject axisJson(const Mc1AxisState& state) {
    return QJsonObject{{QStringLiteral("axis"), state.axis},
                       {QStringLiteral("position"), state.position},
                       {QStringLiteral("target"), state.target},
                       {QStringLiteral("moving"), state.moving},
                       {QStringLiteral("homed"), state.homed},
                       {QStringLiteral("error"), state.error},
                       {QStringLiteral("provisional"), state.provisional}};
}

QString axisLines(const Mc1AxisState& state, const QString& parameters) {
    return QStringLiteral(
               "axis: %1\nposition: %2\ntarget: %3\nmoving: %4\nhomed: %5\nerror: %6\n"
               "state: %7\nparameters: %8\n")
        .arg(state.axis)
        .arg(state.position)
        .arg(state.target)
        .arg(state.moving ? 1 : 0)
        .arg(state.homed ? 1 : 0)
        .arg(state.error ? 1 : 0)
        .arg(state.summary(), parameters);
}

// What was read and through which parameter numbers, or what an
// acknowledged command did and, separately, what reading back found.
struct AxisAnswer {
    std::optional<QString> done;  // a command: its text (it was acknowledged)
    comm::Mc1AxisDone axis;
    QString parameters;  // "provisional: CamBench's built-in guess ..." / the file
};

int printAxis(const AxisAnswer& answer, bool json) {
    const comm::Mc1AxisDone& axis = answer.axis;
    if (json) {
        QJsonObject object =
            axis.after ? axisJson(*axis.after)
                       : QJsonObject{{QStringLiteral("readBackError"), axis.readBackProblem}};
        if (answer.done) {
            object.insert(QStringLiteral("command"), *answer.done);
            object.insert(QStringLiteral("acknowledged"), true);
        }
        object.insert(QStringLiteral("parameters"), answer.parameters);
        return printJson(QJsonDocument(object));
    }
    QString text;
    if (answer.done) text += QStringLiteral("done: %1 (acknowledged)\n").arg(*answer.done);
    if (axis.after)
        text += axisLines(*axis.after, answer.parameters);
    else
        text += QStringLiteral("read-back: failed (the command itself was acknowledged): %1\n")
                    .arg(axis.readBackProblem);
    printOut(text);
    return ExitOk;
}

QString parametersText(const comm::Mc1AxisParameterTable& table) {
    return table.provisional ? QStringLiteral(
                                   "provisional: %1; load the controller's own with "
                                   "--parameters FILE")
                                   .arg(table.source)
                             : table.source;
}

// `mc axis all stop`: every axis the controller has, stops first,
// read-backs after; one line each.
int runMc1StopAll(CliSession& session, CommandArgs& args) {
    if (const Result<QString> verb = takeVerb(args, {QStringLiteral("stop")}); !verb)
        return reportError(verb.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<comm::MotionStopReport> report = runOnMc1<comm::MotionStopReport>(
        session, QStringLiteral("mc axis all stop"),
        [](Mc1Device& device, JobContext&) -> Result<comm::MotionStopReport> {
            comm::MotionControl* motion = device.motionControl();
            if (!motion) {
                const Result<comm::Mc1Axes> axes = device.axes();
                return Error::usage(QStringLiteral("this connection moves no axis: %1")
                                        .arg(axes ? axes->source : axes.error().message));
            }
            return motion->stopAllMotion();
        });
    if (!report) return reportError(report.error());
    QString text;
    for (const comm::MotionStopLine& line : report->lines)
        text += line.absent ? QStringLiteral("%1: %2\n").arg(line.what, line.detail)
                            : QStringLiteral("%1: %2; %3\n")
                                  .arg(line.what,
                                       line.acknowledged ? QStringLiteral("acknowledged")
                                                         : QStringLiteral("NOT acknowledged"),
                                       line.detail);
    printOut(text);
    if (report->allAcknowledged()) return ExitOk;
    return reportError(Error::communication(
        QStringLiteral("not every stop was acknowledged: use the machine's emergency stop")));
}

Result<qint32> parseValue(const QString& text, const QString& what) {
    bool ok = false;
    const qint64 value = text.toLongLong(&ok);
    if (!ok || value < std::numeric_limits<qint32>::min() ||
        value > std::numeric_limits<qint32>::max())
        return Error::usage(
            QStringLiteral("%1 must be a whole number of 32 bits, not \"%2\"").arg(what, text));
    return qint32(value);
}

}  // namespace

int runMc1Program(CliSession& session, CommandArgs& args, const QString& verb) {
    Mc1ProgramCommand command = Mc1ProgramCommand::Start;
    if (verb == QLatin1String("flash")) {
        const Result<QString> which =
            takeVerb(args, {QStringLiteral("save"), QStringLiteral("load")});
        if (!which) return reportError(which.error());
        command = *which == QLatin1String("save") ? Mc1ProgramCommand::FlashSave
                                                  : Mc1ProgramCommand::FlashLoad;
    } else {
        command = verb == QLatin1String("run")    ? Mc1ProgramCommand::Start
                  : verb == QLatin1String("stop") ? Mc1ProgramCommand::Stop
                  : verb == QLatin1String("step") ? Mc1ProgramCommand::Step
                                                  : Mc1ProgramCommand::Reset;
    }
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<comm::Mc1Done<comm::Mc1ProgramStatus>> done =
        runOnMc1<comm::Mc1Done<comm::Mc1ProgramStatus>>(
            session, QStringLiteral("mc ") + verb,
            [command](Mc1Device& device, JobContext&) { return device.programCommand(command); });
    if (!done) return reportError(done.error());
    // Acknowledged is done; a status that could not be read is said apart.
    printOut(done->after ? QStringLiteral("program: %1\n").arg(done->after->summary())
                         : QStringLiteral("done: %1 (acknowledged)\nread-back: failed (the "
                                          "command itself was acknowledged): %2\n")
                               .arg(comm::mc1ProgramCommandText(command), done->readBackProblem));
    return ExitOk;
}

int runMc1Axis(CliSession& session, CommandArgs& args) {
    const Result<QString> axisText =
        args.takeRequiredPositional(QStringLiteral("an axis N or all"));
    if (!axisText) return reportError(axisText.error());
    if (*axisText == QLatin1String("all")) return runMc1StopAll(session, args);
    const Result<int> axis = parseIntArgument(*axisText, QStringLiteral("axis"),
                                              comm::kMc1FirstAxis, comm::kMc1LastAxis);
    if (!axis) return reportError(axis.error());
    const Result<QString> verb =
        takeVerb(args, {QStringLiteral("status"), QStringLiteral("home"), QStringLiteral("stop"),
                        QStringLiteral("quickstop"), QStringLiteral("ack"), QStringLiteral("move"),
                        QStringLiteral("jog"), QStringLiteral("speed")});
    if (!verb) return reportError(verb.error());
    const bool json = args.takeFlag(QStringLiteral("--json"));
    std::optional<Mc1AxisCommand> command;
    qint32 value = 0;
    if (*verb == QLatin1String("move")) {
        const Result<QString> absolute = args.takeOption(QStringLiteral("--abs"));
        const Result<QString> relative = args.takeOption(QStringLiteral("--rel"));
        if (!absolute) return reportError(absolute.error());
        if (!relative) return reportError(relative.error());
        if (absolute->isEmpty() == relative->isEmpty())
            return reportError(
                Error::usage(QStringLiteral("mc axis N move needs --abs VALUE or --rel VALUE")));
        const bool isAbsolute = !absolute->isEmpty();
        const Result<qint32> parsed =
            parseValue(isAbsolute ? *absolute : *relative,
                       isAbsolute ? QStringLiteral("--abs") : QStringLiteral("--rel"));
        if (!parsed) return reportError(parsed.error());
        value = *parsed;
        command = isAbsolute ? Mc1AxisCommand::MoveAbsolute : Mc1AxisCommand::MoveRelative;
    } else if (*verb == QLatin1String("jog")) {
        const Result<QString> direction =
            args.takeRequiredPositional(QStringLiteral("a direction + or -"));
        if (!direction) return reportError(direction.error());
        if (*direction != QLatin1String("+") && *direction != QLatin1String("-"))
            return reportError(Error::usage(
                QStringLiteral("mc axis N jog needs + or -, not \"%1\"").arg(*direction)));
        command =
            *direction == QLatin1String("+") ? Mc1AxisCommand::JogPlus : Mc1AxisCommand::JogMinus;
    } else if (*verb == QLatin1String("speed")) {
        const Result<QString> text = args.takeRequiredPositional(QStringLiteral("a speed"));
        if (!text) return reportError(text.error());
        const Result<qint32> parsed = parseValue(*text, QStringLiteral("speed"));
        if (!parsed) return reportError(parsed.error());
        value = *parsed;
        command = Mc1AxisCommand::SetSpeed;
    } else if (*verb != QLatin1String("status")) {
        command = *verb == QLatin1String("home")   ? Mc1AxisCommand::Home
                  : *verb == QLatin1String("stop") ? Mc1AxisCommand::Stop
                  : *verb == QLatin1String("ack")  ? Mc1AxisCommand::AcknowledgeError
                                                   : Mc1AxisCommand::QuickStop;
    }
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<AxisAnswer> answer = runOnMc1<AxisAnswer>(
        session, QStringLiteral("mc axis"),
        [axis = *axis, command, value](Mc1Device& device, JobContext&) -> Result<AxisAnswer> {
            AxisAnswer answer;
            answer.parameters = parametersText(device.axisParameters());
            if (!command) {
                const Result<Mc1AxisState> state = device.axisState(axis);
                if (!state) return state.error();
                answer.axis.after = *state;
                return answer;
            }
            const Result<comm::Mc1AxisDone> done = device.axisCommand(axis, *command, value);
            if (!done) return done.error();
            answer.done = comm::mc1AxisCommandText(axis, *command, value);
            answer.axis = *done;
            return answer;
        });
    if (!answer) return reportError(answer.error());
    return printAxis(*answer, json);
}

}  // namespace cambench::cli
