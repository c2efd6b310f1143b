#pragma once

#include "model/machine/machine_file.h"
#include "model/result.h"

#include <QList>
#include <QObject>
#include <QPointer>

namespace cambench {

class MachineStop;
class MachineUnit;
class MachineWindow;

// A machine in the GUI (File → Open machine…): its devices, each a
// MachineUnit with its own connection, worker and edits, their one STOP,
// and the window that lists them. The window is rebuilt on a language
// switch; the devices and their lines stay.
class Machine : public QObject {
    Q_OBJECT
public:
    // `path`: the machine file it was read from (empty: not saved yet).
    Machine(const MachineFile& file, QString path, QObject* parent = nullptr);
    ~Machine() override;

    QString name() const { return m_name; }
    QString path() const { return m_path; }
    QList<MachineUnit*> units() const { return m_units; }
    MachineUnit* unit(const QString& name) const;
    MachineStop* stop() const { return m_stop; }
    MachineWindow* window() const;
    // The machine file of the devices as they are now.
    MachineFile file() const;

    // Shows the window and connects every device, each on its own line.
    void open();
    void rebuildWindow();
    // Adds a device (New machine, Detect on a port) and connects it; a
    // name the machine has already is refused.
    Result<MachineUnit*> addDevice(const MachineDevice& device);
    // Writes the machine file; from now on it is the machine's path.
    Status save(const QString& path);

Q_SIGNALS:
    void languageRequested(const QString& language);
    void deviceAdded(cambench::MachineUnit* unit);
    // The window was closed (every device asked): the machine may go.
    void closed();

private:
    MachineUnit* createUnit(const MachineDevice& device);
    void createWindow();

    QString m_name;
    QString m_path;
    QString m_shaftFrom;
    QString m_shaftTo;
    MachineStop* m_stop;
    QList<MachineUnit*> m_units;
    QPointer<MachineWindow> m_window;
};

}  // namespace cambench
