// `help [COMMAND]`: the whole --help, or the lines about one command (a
// usage error points here rather than printing the whole help).
#include "cli_output.h"
#include "commands.h"
#include "exit_codes.h"

namespace cambench::cli {

int runHelp(CliSession&, CommandArgs& args) {
    const QString name = args.takePositional();
    if (const Status done = args.finish(); !done) return reportError(done.error());
    if (name.isEmpty()) {
        printOut(usageText());
        return ExitOk;
    }
    const QString lines = CommandRegistry::instance().helpFor(name);
    if (lines.isEmpty())
        return reportError(
            Error::usage(QStringLiteral("help: there is no command \"%1\"").arg(name)));
    printOut(QStringLiteral("cambench-cli [OPTIONS] %1 ...   (OPTIONS: `cambench-cli --help`; they "
                            "may come before or after the command)\n%2")
                 .arg(name, lines));
    return ExitOk;
}

}  // namespace cambench::cli
