#include "app/registry/builtin_registry.h"
#include "cambench_version.h"
#include "command_line.h"
#include "commands.h"

#include <QCoreApplication>
#include <QLoggingCategory>

int main(int argc, char* argv[]) {
    cambench::registerBuiltins();
    cambench::cli::registerCliCommands();
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("cambench-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(CAMBENCH_VERSION_TEXT));

    // stderr carries one clear line per problem; the components' logs would
    // drown it. QT_LOGGING_RULES still turns them on for debugging.
    QLoggingCategory::setFilterRules(QStringLiteral("cambench.*=false"));
    return cambench::cli::runCommandLine(app.arguments().mid(1));
}
