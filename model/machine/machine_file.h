#pragma once

#include "model/device_identity.h"
#include "model/result.h"

#include <QByteArray>
#include <QList>
#include <QPair>
#include <QString>
#include <QStringList>

#include <optional>

namespace cambench {

// One device of a machine: its name, its family and how to reach it, in
// the command line's own option names ("port", "protocol", "baud" and its
// protocol's options, machineDeviceKeys()), in the file's order; and,
// once known, its identity ("identity": {"serial": ..., "type": ...}): the
// device that belongs there, so that another one answering is said
// (`machine status`, `machine backup`; issue 36); and the items that change
// by themselves, never a difference in the machine's history ("volatile":
// ["V100-V199"], model/machine/volatile_items.h; issue 37).
struct MachineDevice {
    QString name;
    QString family;
    QList<QPair<QString, QString>> options;
    DeviceIdentity identity;
    QStringList volatileItems;

    QString option(const QString& key) const;
    // The options as command-line arguments: --family F --port P ...
    QStringList arguments() const;
};

// A machine file: a press with a cam controller, a motion controller and a
// drive, say (README, "A machine of several devices"):
//   {"machine": "Press 7", "devices": [{"name": "cams", "family": ...,
//    "port": "/dev/ttyUSB0", "protocol": ...}, ...]}
// Optionally "shaft": {"from": DEVICE, "to": DEVICE} for the simulated
// machine (the CamCon's position follows a drive's), with "axis": N (the
// driving device's axis, 1-based; default 1) and "per-turn": U (the
// driving axis's units per turn of the follower; default the simulator's,
// 360).
struct MachineFile {
    QString machine;
    QList<MachineDevice> devices;
    QString shaftFrom;
    QString shaftTo;
    std::optional<int> shaftAxis;
    std::optional<double> shaftPerTurn;

    const MachineDevice* device(const QString& name) const;
};

// "device 2 (feed)": how messages name the device at `index` (0-based).
QString machineDeviceLabel(int index, const QString& name);

// The option names a device may carry besides "name", "family",
// "identity" and "volatile": the line's ("port", "protocol", "baud") and
// each registered protocol's options, which app/registry adds as it
// registers a family (model/ knows no protocol).
QStringList machineDeviceKeys();
void addMachineDeviceKeys(const QStringList& keys);

// Parses a machine file. `where` names it in messages (its path). A wrong
// key, a duplicate or missing name, a value that is neither text nor a
// whole number is refused naming the device ("device 2 (feed)"); whether
// the family and the options fit together is the command line's check.
Result<MachineFile> parseMachineFile(const QByteArray& bytes, const QString& where);

// The file's text: "machine", "devices" (each "name", "family", then its
// options in their order, whole numbers as numbers, then its "volatile"
// items and its "identity" when known) and "shaft", in that
// order, one device a line: saving twice gives the same bytes, and a
// changed device is one changed line. parseMachineFile() reads it back.
QByteArray machineFileJson(const MachineFile& machine);

}  // namespace cambench
