#pragma once

// The history dialog's work on the devices (issue 37): a version's folder
// against every device now, each device's plan of restoring it, and the
// restore - each device on its own worker (its MachineUnit's session), all
// at once, the answer once every device has answered. The machine use
// cases (comm/usecases/machine_backup.h) do the work: the identity first
// (another device is said and nothing is read from, compared with or
// written to it), then its family's part. Names no family.

#include "comm/usecases/machine_backup.h"
#include "comm/usecases/machine_history.h"

#include <QList>
#include <QObject>
#include <QString>

#include <functional>
#include <optional>

namespace cambench {

class Machine;

class MachineHistoryJobs : public QObject {
    Q_OBJECT
public:
    explicit MachineHistoryJobs(Machine* machine, QObject* parent = nullptr);

    bool busy() const { return m_pending > 0; }

    // Each device of the machine backed up now (on its own line; nothing
    // is written to a device) into a temporary folder and compared with
    // the version in the folder `dir` as `machine watch` compares them
    // (usecases::compareWithDevicesNow): a device the version lacks is
    // added, one only in the version taken out of the machine, the
    // volatile items of both machine files left out. `done` gets the
    // changes and the backup now - its folder's files are the devices as
    // they are now, for a family's drawing; the folder is removed once
    // `done` returns. History → Compare with the devices now, and the
    // machine report's changes since the released version.
    void compareWithDevices(const QString& dir,
                            std::function<void(const usecases::MachineChanges& changes,
                                               const usecases::MachineFolderRead& now)>
                                done);

    // One device's plan of a restore: what it will write, or why nothing.
    struct DevicePlan {
        QString name;
        std::optional<usecases::RestorePlan> plan;
        QString why;  // not reached, another device answers, the file does not fit
    };
    void plan(const QString& dir, std::function<void(QList<DevicePlan>)> done);

    // The restore of `names` (the devices whose plan was listed); the safety
    // copies go into `safetyDir`. One line per device.
    struct DeviceRestored {
        QString name;
        bool ok = false;
        QString text;
    };
    void restore(const QString& dir, const QStringList& names, const QString& safetyDir,
                 std::function<void(QList<DeviceRestored>)> done);

private:
    // Runs `work` for each saved device of `dir` that the machine has (the
    // names given, or all); `done` once every one has answered, in the
    // machine's order.
    template <class T>
    void forEachDevice(const QString& dir, const QStringList& names,
                       std::function<Result<T>(const ManifestEntry&, comm::JobContext&)> work,
                       std::function<void(QList<QPair<QString, Result<T>>>)> done);

    Machine* m_machine;
    int m_pending = 0;
};

}  // namespace cambench
