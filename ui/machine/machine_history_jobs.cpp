#include "machine_history_jobs.h"

#include "machine.h"
#include "machine_unit.h"

#include "comm/device/device_connection.h"
#include "model/machine/volatile_items.h"
#include "ui/device_session.h"

#include <QDir>
#include <QPair>

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

void MachineHistoryJobs::compareWithDevices(const QString& dir,
                                            std::function<void(usecases::MachineChanges)> done) {
    const Result<usecases::MachineFolderRead> folder = usecases::readMachineFolder(dir);
    const MachineFile now = m_machine->file();
    QStringList present;
    for (const MachineUnit* unit : m_machine->units()) present << unit->name();
    forEachDevice<usecases::DeviceVerified>(
        dir, {},
        [dir](const ManifestEntry& entry, comm::JobContext& job) {
            return usecases::verifyMachineDevice(job, entry, dir, ReplacementConsent{});
        },
        [folder, now, present,
         done](QList<QPair<QString, Result<usecases::DeviceVerified>>> answers) {
            usecases::MachineChanges changes;
            for (const auto& [name, verified] : answers) {
                usecases::DeviceChange change;
                change.name = name;
                if (!verified) {
                    change.kind = usecases::DeviceChange::Kind::NotSaved;
                    change.why = verified.error().message;
                } else if (!verified->checked.another.isEmpty()) {
                    change.kind = usecases::DeviceChange::Kind::NotSaved;
                    change.why = anotherDeviceWhy(
                        verified->checked,
                        QT_TRANSLATE_NOOP("cambench::MachineHistoryJobs", "It was not compared."));
                } else {
                    QStringList items;
                    if (const MachineDevice* device = now.device(name))
                        items << device->volatileItems;
                    if (folder)
                        if (const MachineDevice* device = folder->machine.device(name))
                            items << device->volatileItems;
                    change.differences = usecases::withoutVolatile(verified->comparison.differences,
                                                                   items, &change.volatileLeftOut);
                    change.kind = change.differences.isEmpty()
                                      ? usecases::DeviceChange::Kind::Equal
                                      : usecases::DeviceChange::Kind::Changed;
                }
                changes.devices << change;
            }
            // A device of the version that the machine no longer has is
            // said, not left out.
            if (folder)
                for (const MachineDevice& device : folder->machine.devices)
                    if (!present.contains(device.name))
                        changes.devices << usecases::DeviceChange{
                            device.name, usecases::DeviceChange::Kind::Removed, {}, 0, {}, {}};
            done(changes);
        });
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
