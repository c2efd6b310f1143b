#pragma once

#include "app/cli/commands.h"

#include "comm/mc1/mc1_device.h"

namespace cambench::cli {

// A cambench-cli job on an MC100/MC200.
template <class T>
using Mc1Work = CliSession::Work<comm::Mc1Device, T>;

template <class T>
Result<T> runOnMc1(CliSession& session, const QString& title, Mc1Work<T> work) {
    return session.run<comm::Mc1Device, T>(title, std::move(work));
}

// The MC-1 family's command group `mc` and its part of --help.
void registerMc1Commands(FamilyCommands& commands);

// Defined in one file per kind of work.
int runMc1Info(CliSession& session, CommandArgs& args);
int runMc1Variables(CliSession& session, CommandArgs& args);
int runMc1Points(CliSession& session, CommandArgs& args, bool io);
int runMc1Program(CliSession& session, CommandArgs& args, const QString& verb);
int runMc1Axis(CliSession& session, CommandArgs& args);
int runMc1Memory(CliSession& session, CommandArgs& args);
int runMc1Backup(CliSession& session, CommandArgs& args);
int runMc1Verify(CliSession& session, CommandArgs& args);
int runMc1Restore(CliSession& session, CommandArgs& args);

// "12" or "12-20": a range of numbers in [min, max].
Result<std::pair<int, int>> parseMc1Range(const QString& text, const QString& what, int min,
                                          int max);
// "0x1000" or "4096".
Result<int> parseMc1Address(const QString& text, const QString& what, int max);

}  // namespace cambench::cli
