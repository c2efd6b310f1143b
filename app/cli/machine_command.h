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

// Who the device on `session` is: its family's identify() for a person and
// its identity (DeviceConnection::readIdentity) to compare, for status,
// the backup's manifest, verify and restore alike.
struct MachineDeviceIdentity {
    QString text;
    DeviceIdentity identity;
};
Result<MachineDeviceIdentity> identifyMachineDevice(CliSession& session, const QString& name);

// The devices `names` (--replacement a,b) are: refused naming the one the
// machine lacks.
Status checkDeviceNames(const MachineFile& machine, const QStringList& names,
                        const QString& option);

// machine status / backup / verify / restore; each returns the exit code.
// `replacements`: the devices the person accepts in place of the ones
// recorded (machine backup records their new identity; machine restore
// writes their backup into them).
int runMachineStatus(const MachineSetup& setup, bool json);
int runMachineBackup(const MachineSetup& setup, const QString& machinePath, const QString& dir,
                     bool resume, const QStringList& replacements);
int runMachineVerify(const QString& dir, const QStringList& replacements);
int runMachineRestore(const QString& dir, const QStringList& only, const QStringList& replacements);

}  // namespace cambench::cli
