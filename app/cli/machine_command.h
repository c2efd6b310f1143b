#pragma once

#include "cli_options.h"
#include "cli_session.h"

#include "model/machine/machine_file.h"

#include <QByteArray>
#include <QList>
#include <QString>
#include <QStringList>

namespace cambench::cli {

// A machine file with every device's options parsed as the command line
// parses them: nothing is asked of a device before all of them fit.
struct MachineSetup {
    MachineFile machine;
    QList<GlobalOptions> options;  // one per device, in the file's order
};

// `where` names the file in messages. A device whose options do not fit
// (a wrong family, a protocol of another family) is refused naming it.
Result<MachineSetup> loadMachine(const QByteArray& bytes, const QString& where);

// Who the device on `session` is (its family's identify()), for status and
// the backup's manifest alike.
Result<QString> identifyMachineDevice(CliSession& session, const QString& name);

// machine status / backup / verify / restore; each returns the exit code.
int runMachineStatus(const MachineSetup& setup, bool json);
int runMachineBackup(const MachineSetup& setup, const QByteArray& machineFile, const QString& dir,
                     bool resume);
int runMachineVerify(const QString& dir);
int runMachineRestore(const QString& dir, const QStringList& only);

}  // namespace cambench::cli
