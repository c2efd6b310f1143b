#pragma once

#include "model/machine/machine_file.h"

#include <QList>
#include <QObject>
#include <QPointer>

namespace cambench {

class DeviceSession;
class FamilyGui;
class MainWindow;
class StopControl;

// One device of a machine in the GUI: what the shell is for a single
// device, once per device - its own connection on its own worker
// (DeviceSession), its own families' data on the PC (edits), and its own
// window of pages, shown inside the machine's window. Nothing of it is
// remembered for the next start (the single device's last connection and
// window layout stay the shell's).
class MachineUnit : public QObject {
    Q_OBJECT
public:
    MachineUnit(MachineDevice device, StopControl* machineStop, QObject* parent = nullptr);
    ~MachineUnit() override;

    const MachineDevice& device() const { return m_device; }
    QString name() const { return m_device.name; }
    DeviceSession* session() const { return m_session; }
    QList<FamilyGui*> families() const { return m_families; }
    MainWindow* window() const;

    // A new window of its pages (the one before is deleted): at the start
    // and after a language switch. Owned by whoever shows it.
    MainWindow* createWindow();
    // Connects as the machine file says and reads what a person looks at
    // first; a device the file describes wrongly is not connected
    // (problem() says why).
    void connectDevice();

    // Moving: connected, and its own live status says that it moves.
    enum class Lamp { Connected, Connecting, Gone, Offline, Moving };
    Lamp lamp() const;
    // The lamp in words: "connected", "connected, moving (...)",
    // "connected, may move: jog + sent at ...", "connection lost: ...", ...
    QString stateText() const;
    QString problem() const { return m_problem; }
    int unwrittenCount() const;

Q_SIGNALS:
    // The lamp, its text or the unwritten count changed.
    void changed();
    void languageRequested(const QString& language);

private:
    MachineDevice m_device;
    StopControl* m_machineStop;
    DeviceSession* m_session;
    QList<FamilyGui*> m_families;
    QPointer<MainWindow> m_window;
    QString m_problem;
};

}  // namespace cambench
