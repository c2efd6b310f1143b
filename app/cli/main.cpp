#include "app/registry/builtin_registry.h"
#include "cambench_version.h"
#include "cli_options.h"
#include "cli_output.h"
#include "cli_session.h"
#include "commands.h"
#include "exit_codes.h"

#include <QCoreApplication>
#include <QLoggingCategory>

#include <cstdio>

using namespace cambench;
using namespace cambench::cli;

int main(int argc, char* argv[]) {
    cambench::registerBuiltins();
    registerCliCommands();
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("cambench-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(CAMBENCH_VERSION_TEXT));

    // stderr carries one clear line per problem; the components' logs would
    // drown it. QT_LOGGING_RULES still turns them on for debugging.
    QLoggingCategory::setFilterRules(QStringLiteral("cambench.*=false"));

    const QStringList args = app.arguments().mid(1);
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
