// c3 enable, disable, stop, jog, move: the motion sequence of the drive
// (comm/compax3/compax3_drive_motion.cpp); each prints the axis afterwards.
#include "compax3_commands.h"

#include "app/cli/cli_output.h"
#include "app/cli/exit_codes.h"

namespace cambench::cli {

namespace {

using comm::Compax3Device;
using comm::Compax3Motion;
using comm::JobContext;

Result<std::optional<double>> numberOption(CommandArgs& args, const QString& name) {
    const Result<QString> text = args.takeOption(name);
    if (!text) return text.error();
    if (text->isEmpty()) return std::optional<double>();
    const std::optional<double> number = compax3Number(*text);
    if (!number)
        return Error::usage(
            QStringLiteral("%1 needs a number with a decimal point, not \"%2\"").arg(name, *text));
    return std::optional<double>(*number);
}

// Acknowledged is done (exit 0); a read-back that failed afterwards is a
// note, never a failure of the command.
int printAxis(const QString& what, const Result<comm::Compax3CommandResult>& result) {
    if (!result) return reportError(result.error());
    QString text;
    if (!result->note.isEmpty())
        text += QStringLiteral("note: %1\n").arg(result->note);
    else
        text += QStringLiteral("done: %1 (acknowledged by the drive)\n").arg(what);
    if (result->after)
        text += QStringLiteral("axis: %1\nlast error: %2\n")
                    .arg(result->after->summary(),
                         comm::compax3LastErrorText(result->after->lastError));
    printOut(text);
    if (!result->after)
        printError(
            QStringLiteral("note: %1; the command itself was acknowledged").arg(result->summary()));
    return ExitOk;
}

}  // namespace

int runCompax3Motion(CliSession& session, CommandArgs& args, const QString& verb) {
    if (verb == QLatin1String("move")) {
        const Result<QString> setText = args.takeRequiredPositional(QStringLiteral("a set N"));
        if (!setText) return reportError(setText.error());
        const Result<int> set =
            parseIntArgument(*setText, QStringLiteral("the set"), 0, comm::kCompax3LastSetNumber);
        if (!set) return reportError(set.error());
        comm::Compax3SetMove move;
        move.set = *set;
        const std::pair<const char*, std::optional<double>*> options[] = {
            {"--target", &move.target},
            {"--velocity", &move.velocity},
            {"--accel", &move.acceleration},
            {"--decel", &move.deceleration}};
        for (const auto& [name, target] : options) {
            const Result<std::optional<double>> value = numberOption(args, QLatin1String(name));
            if (!value) return reportError(value.error());
            *target = *value;
        }
        if (const Status done = args.finish(); !done) return reportError(done.error());
        return printAxis(
            comm::compax3SetMoveText(move),
            runOnCompax3<comm::Compax3CommandResult>(
                session, QStringLiteral("c3 move"),
                [move](Compax3Device& device, JobContext&) { return device.moveSet(move); }));
    }
    Compax3Motion motion = Compax3Motion::Stop;
    if (verb == QLatin1String("enable")) motion = Compax3Motion::Enable;
    if (verb == QLatin1String("disable")) motion = Compax3Motion::Disable;
    if (verb == QLatin1String("jog")) {
        const Result<QString> direction =
            takeVerb(args, {QStringLiteral("+"), QStringLiteral("-")});
        if (!direction) return reportError(direction.error());
        motion =
            *direction == QLatin1String("+") ? Compax3Motion::JogPlus : Compax3Motion::JogMinus;
    }
    if (const Status done = args.finish(); !done) return reportError(done.error());
    return printAxis(
        comm::compax3MotionText(motion),
        runOnCompax3<comm::Compax3CommandResult>(
            session, QStringLiteral("c3 %1").arg(verb),
            [motion](Compax3Device& device, JobContext&) { return device.motion(motion); }));
}

}  // namespace cambench::cli
