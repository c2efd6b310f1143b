#include "commands.h"

namespace cambench::cli {

const CommandGroup* findCommandGroup(const QString& name) {
    static const CommandGroup kGroups[] = {
        {"info", runInfo},
        {"status", runStatus},
        {"scan", runScan},
        {"ports", runPorts},
        {"raw", runRaw},
        {"cams", runCams},
        {"deadtimes", runDeadTimes},
        {"names", runNames},
        {"settings", runSettings},
        {"users", runUsers},
        {"plc", runPlc},
        {"backup", runBackup},
        {"restore", runRestore},
        {"verify", runVerify},
        {"project", runProject},
        {"backup-line", runBackupLine},
        {"verify-line", runVerifyLine},
        {"short", runShortCommands},
        {"analogue", runAnalogue},
        {"programming", runProgramming},
        {"eeprom-lock", runEepromLock},
    };
    for (const CommandGroup& group : kGroups) {
        if (name == QLatin1String(group.name)) return &group;
    }
    return nullptr;
}

Result<QString> takeVerb(CommandArgs& args, const QStringList& verbs) {
    const QString verb = args.takePositional();
    if (verbs.contains(verb)) return verb;
    return Error::usage(
        QStringLiteral("%1 needs one of: %2%3; see `cambench-cli --help`")
            .arg(args.command(), verbs.join(QLatin1String(", ")),
                 verb.isEmpty() ? QString() : QStringLiteral(" (not \"%1\")").arg(verb)));
}

}  // namespace cambench::cli
