#include "machine_history_jobs.h"

#include "machine.h"
#include "machine_unit.h"

#include "comm/device/device_connection.h"
#include "ui/device_session.h"

#include <QDir>
#include <QPair>
#include <QTemporaryDir>

#include <memory>

namespace cambench {

namespace {

QString tr(const char* text) {
    return QCoreApplication::translate("cambench::MachineHistoryJobs", text);
}

// Why nothing was compared with or written to a device whose identity
// check found another one.
QString anotherDeviceWhy(const usecases::DeviceChecked& checked, const char* nothing) {
    return QStringLiteral("%1. %2").arg(checked.another, tr(nothing));
}

}  // namespace

MachineHistoryJobs::MachineHistoryJobs(Machine* machine, QObject* parent)
    : QObject(parent), m_machine(machine) {}

template <class T>
void MachineHistoryJobs::forEachDevice(
    const QString& dir, const QStringList& names,
    std::function<Result<T>(const ManifestEntry&, comm::JobContext&)> work,
    std::function<void(QList<QPair<QString, Result<T>>>)> done) {
    const Result<usecases::MachineFolderRead> folder = usecases::readMachineFolder(dir);
    using Answers = QList<QPair<QString, Result<T>>>;
    auto answers = std::make_shared<Answers>();
    auto waiting = std::make_shared<int>(0);
    QList<QPair<MachineUnit*, ManifestEntry>> asked;
    for (MachineUnit* unit : m_machine->units()) {
        if (!names.isEmpty() && !names.contains(unit->name())) continue;
        const ManifestEntry* entry = folder ? folder->manifest.entry(unit->name()) : nullptr;
        if (!entry || !entry->saved()) {
            *answers << QPair<QString, Result<T>>(
                unit->name(),
                Error::invalidData(
                    !folder ? folder.error().message
                            : QCoreApplication::translate("cambench::MachineHistoryJobs",
                                                          "not in this version of the machine")));
            continue;
        }
        *answers << QPair<QString, Result<T>>(unit->name(), Error::cancelled());
        asked << QPair<MachineUnit*, ManifestEntry>(unit, *entry);
    }
    if (asked.isEmpty()) {
        done(*answers);
        return;
    }
    *waiting = int(asked.size());
    m_pending += *waiting;
    for (const auto& [unit, entry] : asked) {
        const QString name = unit->name();
        unit->session()->template run<comm::DeviceConnection, T>(
            this,
            QCoreApplication::translate("cambench::MachineHistoryJobs", "%1: %2")
                .arg(name, entry.file),
            [work, entry = entry](comm::DeviceConnection&, comm::JobContext& job) {
                return work(entry, job);
            },
            [this, answers, waiting, name, done](Result<T> result) {
                for (auto& answer : *answers)
                    if (answer.first == name) answer.second = std::move(result);
                --m_pending;
                if (--*waiting == 0) done(*answers);
            });
    }
}

void MachineHistoryJobs::compareWithDevices(
    const QString& dir, std::function<void(const usecases::MachineChanges& changes,
                                           const usecases::MachineFolderRead& now)>
                            done) {
    // The backup now as `machine watch` takes it: one file per device and
    // its manifest line; the machine file is the machine's.
    auto backup = std::make_shared<QTemporaryDir>();
    auto now = std::make_shared<usecases::MachineFolderRead>();
    now->dir = backup->path();
    now->machine = m_machine->file();
    now->manifest.machine = m_machine->name();
    const auto compare = [dir, backup, now, done] {
        done(usecases::compareWithDevicesNow(dir, *now), *now);
    };
    const QList<MachineUnit*> units = m_machine->units();
    for (const MachineUnit* unit : units) {
        ManifestEntry entry;
        entry.name = unit->name();
        entry.family = unit->device().family;
        entry.file = deviceFileName(unit->name());
        if (!backup->isValid())
            entry.result =
                tr("failed: no temporary folder for the backup now: %1").arg(backup->errorString());
        now->manifest.devices << entry;
    }
    if (!backup->isValid() || units.isEmpty()) {
        compare();
        return;
    }
    auto waiting = std::make_shared<int>(int(units.size()));
    m_pending += *waiting;
    for (qsizetype i = 0; i < units.size(); ++i) {
        MachineUnit* unit = units.at(i);
        const MachineDevice device = unit->device();
        const QString into = backup->path();
        unit->session()->run<comm::DeviceConnection, usecases::DeviceBackedUp>(
            this, tr("%1: back up to compare").arg(unit->name()),
            [device, into](comm::DeviceConnection&, comm::JobContext& job) {
                return Result<usecases::DeviceBackedUp>(
                    usecases::backUpMachineDevice(job, device, into, false));
            },
            [this, now, waiting, i, compare](Result<usecases::DeviceBackedUp> taken) {
                ManifestEntry& entry = now->manifest.devices[i];
                if (taken)
                    entry = taken->entry;
                else  // the job never ran (not connected, dropped by a STOP)
                    entry.result = tr("failed: %1").arg(taken.error().message);
                --m_pending;
                if (--*waiting == 0) compare();
            });
    }
}

void MachineHistoryJobs::plan(const QString& dir, std::function<void(QList<DevicePlan>)> done) {
    forEachDevice<usecases::DevicePlanned>(
        dir, {},
        [dir](const ManifestEntry& entry, comm::JobContext& job) {
            return usecases::planMachineDevice(job, entry, dir, usecases::RestoreRequest{});
        },
        [done](QList<QPair<QString, Result<usecases::DevicePlanned>>> answers) {
            QList<DevicePlan> plans;
            for (const auto& [name, planned] : answers) {
                DevicePlan plan{name, std::nullopt, {}};
                if (!planned)
                    plan.why = planned.error().message;
                else if (!planned->checked.another.isEmpty())
                    plan.why = anotherDeviceWhy(
                        planned->checked, QT_TRANSLATE_NOOP("cambench::MachineHistoryJobs",
                                                            "Nothing will be written to it."));
                else
                    plan.plan = planned->plan;
                plans << plan;
            }
            done(plans);
        });
}

void MachineHistoryJobs::restore(const QString& dir, const QStringList& names,
                                 const QString& safetyDir,
                                 std::function<void(QList<DeviceRestored>)> done) {
    if (!QDir().mkpath(safetyDir)) {
        QList<DeviceRestored> none;
        for (const QString& name : names)
            none << DeviceRestored{name, false,
                                   QCoreApplication::translate(
                                       "cambench::MachineHistoryJobs",
                                       "NOT RESTORED: cannot make the folder %1 for the safety "
                                       "copies; nothing was written.")
                                       .arg(safetyDir)};
        done(none);
        return;
    }
    forEachDevice<usecases::DeviceRestored>(
        dir, names,
        [dir, safetyDir](const ManifestEntry& entry, comm::JobContext& job) {
            usecases::RestoreRequest request;
            request.safetyCopy = QDir(safetyDir).filePath(entry.file);
            return usecases::restoreMachineDevice(job, entry, dir, request);
        },
        [done, safetyDir](QList<QPair<QString, Result<usecases::DeviceRestored>>> answers) {
            QDir().rmdir(safetyDir);  // only when no family took a copy into it
            QList<DeviceRestored> lines;
            for (const auto& [name, restored] : answers) {
                if (!restored) {
                    lines << DeviceRestored{name, false,
                                            QCoreApplication::translate(
                                                "cambench::MachineHistoryJobs", "NOT RESTORED: %1")
                                                .arg(restored.error().message)};
                } else if (!restored->checked.another.isEmpty()) {
                    lines << DeviceRestored{
                        name, false,
                        QCoreApplication::translate("cambench::MachineHistoryJobs",
                                                    "NOT RESTORED: %1")
                            .arg(
                                anotherDeviceWhy(restored->checked,
                                                 QT_TRANSLATE_NOOP("cambench::MachineHistoryJobs",
                                                                   "Nothing was written to it.")))};
                } else if (!restored->result.ok()) {
                    lines << DeviceRestored{
                        name, false,
                        QCoreApplication::translate("cambench::MachineHistoryJobs",
                                                    "NOT RESTORED completely: %1")
                            .arg(restored->result.outcomes.summary())};
                } else {
                    lines << DeviceRestored{
                        name, true,
                        QCoreApplication::translate("cambench::MachineHistoryJobs", "restored")};
                }
            }
            done(lines);
        });
}

}  // namespace cambench
