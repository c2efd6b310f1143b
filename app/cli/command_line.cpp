#include "command_line.h"

#include "cambench_version.h"
#include "cli_options.h"
#include "cli_output.h"
#include "cli_session.h"
#include "commands.h"
#include "exit_codes.h"

namespace cambench::cli {

namespace {

// The first word of `args` that names a command: what a usage error's help
// line and `COMMAND --help` are about.
QString commandWord(const QStringList& args) {
    for (const QString& arg : args)
        if (CommandRegistry::instance().isCommand(arg)) return arg;
    return {};
}

}  // namespace

int runCommandLine(const QStringList& args) {
    const QString command = commandWord(args);
    if (args.contains(QLatin1String("--help")) || args.contains(QLatin1String("-h"))) {
        const QString lines =
            command.isEmpty() ? QString() : CommandRegistry::instance().helpFor(command);
        printOut(lines.isEmpty() ? usageText() : lines);
        return ExitOk;
    }
    // After a command word --version is the command's (machine restore DIR
    // --version A names a version of the machine's archive).
    if (command.isEmpty() && args.contains(QLatin1String("--version"))) {
        printOut(QStringLiteral("cambench-cli %1\n").arg(QLatin1String(CAMBENCH_VERSION_TEXT)));
        return ExitOk;
    }
    setHelpCommand(command);
    const Result<GlobalOptions> options = parseGlobalOptions(args);
    if (!options) return reportError(options.error());
    const CommandRegistry& commands = CommandRegistry::instance();
    const CommandGroup* group = commands.find(options->family, options->command);
    if (!group) {
        return reportError(
            Error::usage(QStringLiteral("unknown command \"%1\"").arg(options->command)));
    }
    CliSession session(*options);
    CommandArgs commandArgs(options->command, options->commandArgs);
    return group->run(session, commandArgs);
}

}  // namespace cambench::cli
