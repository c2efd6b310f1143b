#include "command_line.h"

#include "cambench_version.h"
#include "cli_options.h"
#include "cli_output.h"
#include "cli_session.h"
#include "commands.h"
#include "exit_codes.h"

namespace cambench::cli {

int runCommandLine(const QStringList& args) {
    if (args.contains(QLatin1String("--help")) || args.contains(QLatin1String("-h"))) {
        printOut(usageText());
        return ExitOk;
    }
    if (args.contains(QLatin1String("--version"))) {
        printOut(QStringLiteral("cambench-cli %1\n").arg(QLatin1String(CAMBENCH_VERSION_TEXT)));
        return ExitOk;
    }
    const Result<GlobalOptions> options = parseGlobalOptions(args);
    if (!options) return reportError(options.error());
    const CommandRegistry& commands = CommandRegistry::instance();
    const CommandGroup* group = commands.find(options->family, options->command);
    if (!group) {
        const QStringList families = commands.familiesWith(options->command);
        if (!families.isEmpty()) {
            return reportError(Error::usage(
                QStringLiteral("\"%1\" is a command of the %2 family, not of %3; add --family %2")
                    .arg(options->command, families.first(), options->family)));
        }
        return reportError(
            Error::usage(QStringLiteral("unknown command \"%1\"; see `cambench-cli --help`")
                             .arg(options->command)));
    }
    CliSession session(*options);
    CommandArgs commandArgs(options->command, options->commandArgs);
    return group->run(session, commandArgs);
}

}  // namespace cambench::cli
