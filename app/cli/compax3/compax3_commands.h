#pragma once

#include "app/cli/commands.h"

#include "comm/compax3/compax3_device.h"
#include "model/compax3/compax3_dictionary.h"

namespace cambench::cli {

// A cambench-cli job on a Compax3.
template <class T>
using Compax3Work = CliSession::Work<comm::Compax3Device, T>;

template <class T>
Result<T> runOnCompax3(CliSession& session, const QString& title, Compax3Work<T> work) {
    return session.run<comm::Compax3Device, T>(title, std::move(work));
}

// The Compax3 family's command group `c3` and its part of --help.
void registerCompax3Commands(FamilyCommands& commands);

// Defined in one file per kind of work; `dictionary` is the shipped one or
// the --dictionary FILE given.
int runCompax3Info(CliSession& session, CommandArgs& args);
int runCompax3Read(CliSession& session, CommandArgs& args, const Compax3Dictionary& dictionary);
int runCompax3Write(CliSession& session, CommandArgs& args, const Compax3Dictionary& dictionary);
int runCompax3Scan(CliSession& session, CommandArgs& args);
int runCompax3Watch(CliSession& session, CommandArgs& args);
int runCompax3Status(CliSession& session, CommandArgs& args);
int runCompax3Motion(CliSession& session, CommandArgs& args, const QString& verb);
int runCompax3Backup(CliSession& session, CommandArgs& args, const Compax3Dictionary& dictionary);
int runCompax3Verify(CliSession& session, CommandArgs& args, const Compax3Dictionary& dictionary);
int runCompax3Restore(CliSession& session, CommandArgs& args, const Compax3Dictionary& dictionary);

// "680.5,1901.1" or several words: objects in the order given.
Result<QList<Compax3ObjectId>> parseCompax3Objects(const QStringList& words);

}  // namespace cambench::cli
