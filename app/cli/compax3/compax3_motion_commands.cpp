// c3 enable, disable, stop, jog, move: the motion sequence of the drive
// (comm/compax3/compax3_drive_motion.cpp); each prints the axis afterwards.
#include "compax3_commands.h"

#include "app/cli/cli_output.h"
#include "app/cli/exit_codes.h"

namespace cambench::cli {

namespace {

using comm::Compax3Device;
using comm::Compax3DriveStatus;
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

int printAxis(const Result<Compax3DriveStatus>& status) {
    if (!status) return reportError(status.error());
    printOut(QStringLiteral("axis: %1\nlast error: %2\n")
                 .arg(status->summary(), comm::compax3LastErrorText(status->lastError)));
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
            {"--accel", &move.acceleration}};
        for (const auto& [name, target] : options) {
            const Result<std::optional<double>> value = numberOption(args, QLatin1String(name));
            if (!value) return reportError(value.error());
            *target = *value;
        }
        if (const Status done = args.finish(); !done) return reportError(done.error());
        return printAxis(runOnCompax3<Compax3DriveStatus>(
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
    return printAxis(runOnCompax3<Compax3DriveStatus>(
        session, QStringLiteral("c3 %1").arg(verb),
        [motion](Compax3Device& device, JobContext&) { return device.motion(motion); }));
}

}  // namespace cambench::cli
