#pragma once

#include "cli_options.h"
#include "cli_session.h"

namespace cambench::cli {

// One command group. `run` parses its own arguments (usage errors before
// any device work), does its work through the session and returns the
// exit code.
struct CommandGroup {
    const char* name;
    int (*run)(CliSession& session, CommandArgs& args);
};

// Defined in one file per group.
int runInfo(CliSession& session, CommandArgs& args);
int runStatus(CliSession& session, CommandArgs& args);
int runScan(CliSession& session, CommandArgs& args);
int runPorts(CliSession& session, CommandArgs& args);
int runRaw(CliSession& session, CommandArgs& args);
int runCams(CliSession& session, CommandArgs& args);
int runDeadTimes(CliSession& session, CommandArgs& args);
int runNames(CliSession& session, CommandArgs& args);
int runSettings(CliSession& session, CommandArgs& args);
int runUsers(CliSession& session, CommandArgs& args);
int runPlc(CliSession& session, CommandArgs& args);
int runBackup(CliSession& session, CommandArgs& args);
int runRestore(CliSession& session, CommandArgs& args);
int runVerify(CliSession& session, CommandArgs& args);
int runProject(CliSession& session, CommandArgs& args);
int runBackupLine(CliSession& session, CommandArgs& args);
int runVerifyLine(CliSession& session, CommandArgs& args);
int runShortCommands(CliSession& session, CommandArgs& args);
int runAnalogue(CliSession& session, CommandArgs& args);
int runProgramming(CliSession& session, CommandArgs& args);
int runEepromLock(CliSession& session, CommandArgs& args);

const CommandGroup* findCommandGroup(const QString& name);

// "read" or "write" after a group name; a usage error for anything else.
Result<QString> takeVerb(CommandArgs& args, const QStringList& verbs);

}  // namespace cambench::cli
