#pragma once

// What the machine window's tests share: a machine file's device, the
// machines of simulated devices, a row of the device list.

#include "shell_fixture.h"

#include "model/machine/machine_file.h"
#include "ui/device_session.h"
#include "ui/machine/machine.h"
#include "ui/machine/machine_unit.h"
#include "ui/machine/machine_window.h"

#include <QTest>
#include <QTreeWidget>

namespace cambench::test {

inline MachineDevice machineDevice(const QString& name, const QString& family,
                                   const QList<QPair<QString, QString>>& options) {
    return MachineDevice{name, family, options, {}, {}};
}

// A CamCon and an MC200 V2, each on its own simulated device, unthrottled.
inline MachineFile camsAndPlc() {
    MachineFile file;
    file.machine = QStringLiteral("Test press");
    file.devices << machineDevice(QStringLiteral("cams"), QStringLiteral("camcon"),
                                  {{QStringLiteral("port"), QStringLiteral("sim:throttle=0")},
                                   {QStringLiteral("protocol"), QStringLiteral("standard")}})
                 << machineDevice(QStringLiteral("press-plc"), QStringLiteral("mc1"),
                                  {{QStringLiteral("port"), QStringLiteral("sim:variant=mc200v2")},
                                   {QStringLiteral("protocol"), QStringLiteral("mc1")},
                                   {QStringLiteral("variant"), QStringLiteral("mc200v2")}});
    return file;
}

// Those two and a Compax3 drive ("feed"): a device of each family.
inline MachineFile threeFamilies() {
    MachineFile file = camsAndPlc();
    file.devices << machineDevice(QStringLiteral("feed"), QStringLiteral("compax3"),
                                  {{QStringLiteral("port"), QStringLiteral("sim")}});
    return file;
}

// Every device on the line and identified (its family's start reads done).
inline bool waitIdentified(const Machine& machine) {
    return QTest::qWaitFor(
        [&machine] {
            for (const MachineUnit* unit : machine.units())
                if (!unit->session()->deviceChecked() ||
                    unit->lamp() != MachineUnit::Lamp::Connected)
                    return false;
            return true;
        },
        kDeviceTimeoutMs);
}

// The device list's row of `name`; nullptr when the list has none.
inline QTreeWidgetItem* machineRow(const Machine& machine, const QString& name) {
    QTreeWidget* list = machine.window()->deviceList();
    for (int i = 0; i < list->topLevelItemCount(); ++i)
        if (list->topLevelItem(i)->text(MachineWindow::Name) == name) return list->topLevelItem(i);
    return nullptr;
}

}  // namespace cambench::test
