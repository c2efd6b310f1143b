#pragma once

// What the machine window's tests share: a machine file's device, the
// machines of simulated devices, a row of the device list.

#include "shell_fixture.h"

#include "model/file_read.h"
#include "model/machine/machine_backup_folder.h"
#include "model/machine/machine_file.h"
#include "ui/device_session.h"
#include "ui/machine/machine.h"
#include "ui/machine/machine_backup_run.h"
#include "ui/machine/machine_unit.h"
#include "ui/machine/machine_window.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QMessageBox>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
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

// A machine open in its window (all its devices connecting), and the path
// of a backup folder `name` in a temporary folder beside it.
struct OpenedMachine {
    Shell shell;
    Machine* machine = nullptr;
    QTemporaryDir folder;
    QString dir;
};
inline std::unique_ptr<OpenedMachine> openWithBackupFolder(const MachineFile& file,
                                                           const QString& name) {
    auto open = std::make_unique<OpenedMachine>();
    open->machine = open->shell.openMachine(file, {});
    open->dir = open->folder.filePath(name);
    return open;
}

// Waits for a backup, verify or restore run's end; false when it did not end in time.
inline bool waitDone(MachineBackupRun* run) {
    QSignalSpy finished(run, &MachineBackupRun::finished);
    return run->isDone() || finished.wait(kDeviceTimeoutMs);
}

// The manifest of the backup folder `dir` (empty when it has none).
inline MachineManifest manifestIn(const QString& dir) {
    const Result<QByteArray> bytes = readFileBytes(QDir(dir).filePath(kMachineManifestFile));
    if (!bytes) return {};
    const Result<MachineManifest> manifest = parseManifest(*bytes, dir);
    return manifest ? *manifest : MachineManifest{};
}

// Writes `manifest` over the one in `dir`, as a hand that edits it does.
inline bool rewriteManifest(const QString& dir, const MachineManifest& manifest) {
    QFile file(QDir(dir).filePath(kMachineManifestFile));
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate) &&
           file.write(manifestJson(manifest)) > 0;
}

// Declines every question that comes up while it lives and keeps their
// object names in the order they came.
class DeclineEveryQuestion {
public:
    DeclineEveryQuestion() {
        m_timer.setInterval(10);
        QObject::connect(&m_timer, &QTimer::timeout, [this] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!box || box->property("answered").toBool()) return;
            box->setProperty("answered", true);
            m_asked << box->objectName();
            box->reject();
        });
        m_timer.start();
    }
    const QStringList& asked() const { return m_asked; }

private:
    QTimer m_timer;
    QStringList m_asked;
};

}  // namespace cambench::test
