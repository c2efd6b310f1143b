#pragma once

// The machine report's "Changes since the released version" (issue 37,
// item 4): every device backed up now and compared with its backup in the
// version released in the machine's archive - the comparison of History →
// Compare with the devices now and of `machine watch`
// (MachineHistoryJobs::compareWithDevices), volatile items left out - and
// said device by device. A device that was
// not compared says so and why; never "equal" for it. Names no family.

#include "comm/usecases/machine_history.h"

#include <QCoreApplication>
#include <QObject>
#include <QString>

#include <functional>

namespace cambench {

class Machine;

struct ReleasedChanges {
    QString archive;  // the archive folder chosen; empty: none was chosen
    // Why nothing was compared: no archive there, no version released, the
    // version could not be taken out. Empty when the devices were compared.
    QString problem;
    // The released version: "released-2: version 1a2b3c4d5e of 2025-11-29
    // 14:03 by alice (commissioning)".
    QString version;
    usecases::MachineChanges changes;
};

class MachineReportChanges {
    Q_DECLARE_TR_FUNCTIONS(cambench::MachineReportChanges)
public:
    // Compares every device of `machine` with the version released in
    // `archive`, each on its own worker; `done` on `context`'s thread once
    // every device answered (at once when there is nothing to compare).
    static void compare(Machine* machine, const QString& archive, QObject* context,
                        std::function<void(ReleasedChanges)> done);
    // What became of one device since the released version, in a word or
    // a sentence ("equal to the released version", "DIFFERS: 2
    // difference(s)", "NOT COMPARED: why").
    static QString deviceLine(const usecases::DeviceChange& change);
    // The report's section (HTML): the version, then a line per device.
    static QString html(const ReleasedChanges& changes);
};

}  // namespace cambench
