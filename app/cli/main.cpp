#include "app/registry/builtin_registry.h"
#include "app/registry/family_parts.h"
#include "cambench_version.h"
#include "command_line.h"
#include "commands.h"
#include "interrupt_watch.h"

#include <QCoreApplication>
#include <QLoggingCategory>

int main(int argc, char* argv[]) {
    cambench::registerBuiltins();
    cambench::cli::registerShellCommands(cambench::cli::CommandRegistry::instance());
    if (!cambench::familiesComplete(cambench::Program::Cli, "cambench-cli"))
        return 70;  // EX_SOFTWARE: this build lacks a family's part
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("cambench-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(CAMBENCH_VERSION_TEXT));

    // stderr carries one clear line per problem; the components' logs would
    // drown it. QT_LOGGING_RULES still turns them on for debugging.
    QLoggingCategory::setFilterRules(QStringLiteral("cambench.*=false"));
    // SIGINT/SIGTERM: nothing that moves or writes leaves after it (interrupt_watch.h).
    cambench::cli::InterruptWatch::install();
    const int code = cambench::cli::runCommandLine(app.arguments().mid(1));
    if (const int signal = cambench::cli::InterruptWatch::received(); signal != 0)
        return 128 + signal;
    return code;
}
