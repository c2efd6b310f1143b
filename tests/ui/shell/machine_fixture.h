#pragma once

// What the machine window's tests share: a machine file's device, a row of
// the device list.

#include "model/machine/machine_file.h"
#include "ui/machine/machine.h"
#include "ui/machine/machine_window.h"

#include <QTreeWidget>

namespace cambench::test {

inline MachineDevice machineDevice(const QString& name, const QString& family,
                                   const QList<QPair<QString, QString>>& options) {
    return MachineDevice{name, family, options, {}};
}

// The device list's row of `name`; nullptr when the list has none.
inline QTreeWidgetItem* machineRow(const Machine& machine, const QString& name) {
    QTreeWidget* list = machine.window()->deviceList();
    for (int i = 0; i < list->topLevelItemCount(); ++i)
        if (list->topLevelItem(i)->text(MachineWindow::Name) == name) return list->topLevelItem(i);
    return nullptr;
}

}  // namespace cambench::test
