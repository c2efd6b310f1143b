#pragma once

#include "app/cli/commands.h"

#include "comm/camcon/camcon_device.h"

namespace cambench::cli {

// A cambench-cli job on a CamCon.
template <class T>
using CamConWork = CliSession::Work<comm::CamConDevice, T>;

template <class T>
Result<T> runOnCamCon(CliSession& session, const QString& title, CamConWork<T> work) {
    return session.run<comm::CamConDevice, T>(title, std::move(work));
}

// The CamCon's command groups and its part of --help.
void registerCamConCommands(FamilyCommands& commands);

// Defined in one file per group.
int runInfo(CliSession& session, CommandArgs& args);
int runStatus(CliSession& session, CommandArgs& args);
int runScan(CliSession& session, CommandArgs& args);
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
int runDiff(CliSession& session, CommandArgs& args);
int runTiming(CliSession& session, CommandArgs& args);

}  // namespace cambench::cli
