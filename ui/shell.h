#pragma once

#include "model/result.h"

#include <QList>
#include <QObject>
#include <QPointer>

namespace cambench {

class DeviceSession;
class FamilyGui;
class Machine;
class MainWindow;
struct MachineFile;

// The application around the window: one session and each registered
// family's GUI part (with what it holds on the PC) for the whole run, and a
// main window that is rebuilt on a language switch (its texts are set when
// it is built) without losing the line or any edit.
class Shell : public QObject {
    Q_OBJECT
public:
    explicit Shell(QObject* parent = nullptr);
    ~Shell() override;

    DeviceSession* session() const { return m_session; }
    QList<FamilyGui*> families() const { return m_families; }
    // A registered family's part ("camcon"), nullptr when there is none.
    FamilyGui* family(const QString& familyId) const;
    MainWindow* window() const { return m_window; }

    // Shows the window as it was left; connects to `port`, or without one
    // to the last connection that worked, and reads identity and program 0;
    // `protocol` (a registry id such as "3964r-n96") chooses the protocol.
    void start(const QString& port, const QString& protocol = {});
    void switchLanguage(const QString& language);

    // A machine's window beside this one (File → Open machine…): every
    // device of `file` on its own line. `path`: where it was read from.
    Machine* openMachine(const MachineFile& file, const QString& path);
    QList<Machine*> machines() const;
    // The machine of the file at `path`; an error names what is wrong.
    Result<Machine*> openMachineFile(const QString& path);

Q_SIGNALS:
    void windowRebuilt(cambench::MainWindow* window);

private:
    MainWindow* createWindow();
    void askForMachineFile();
    void openDemoMachine();
    // A machine whose first device is this window's connection.
    void newMachine();

    DeviceSession* m_session;
    QList<FamilyGui*> m_families;
    QPointer<MainWindow> m_window;
    QList<QPointer<Machine>> m_machines;
};

}  // namespace cambench
