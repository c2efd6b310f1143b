#pragma once

#include <QMainWindow>

class QMenu;
class QStackedWidget;
class QTreeWidget;
class QTreeWidgetItem;

namespace cambench {

class Machine;
class MachineBackupRun;
class MachineProgress;
class MachineUnit;

// The window of a machine: the list of its devices (name, family, port, a
// lamp with the line's state in words, the edits not written) beside the
// selected device's own window of pages and its STOP (the machine's: it
// stops every device). One menu bar: the Machine menu, then the selected
// device's menus (its window's own menu bar is hidden). The STOP key works from every widget
// of the window; the status bar says what the last STOP reached and which
// device went away.
class MachineWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MachineWindow(Machine* machine, QWidget* parent = nullptr);

    QTreeWidget* deviceList() const { return m_list; }
    QString currentDevice() const;
    // Shows `name`'s pages (the first device's when there is no such device).
    void showDevice(const QString& name);
    void showMessage(const QString& text);
    QString lastMessage() const { return m_lastMessage; }

    // Every device is asked (a move to stop, edits not written); true: may close.
    bool confirmClose();
    // Machine → Machine report… to `path`: reads every device first (the
    // dialog shows a bar per device), then writes the PDF. With `archive`
    // (the machine's archive), each device is then compared with the
    // released version there, and the report says what changed since.
    MachineProgress* writeReportTo(const QString& path, const QString& archive = {});
    // Machine → Back up…, Verify…, Restore… with the folder chosen (and
    // the backup's note: why). Each device's line says what became of it.
    MachineBackupRun* backUpTo(const QString& dir, const QString& note);
    MachineBackupRun* verifyFrom(const QString& dir);
    MachineBackupRun* restoreFrom(const QString& dir);

    // The columns of the device list.
    // State and unwritten edits first: a long port or family name must not
    // push them out of sight.
    enum Column { Name = 0, State, Unwritten, Family, Port };

Q_SIGNALS:
    void closed();

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void createMenus();
    // The Machine menu and `unit`'s menus in the one menu bar.
    void showMenusOf(MachineUnit* unit);
    void addRow(MachineUnit* unit);
    void updateRow(MachineUnit* unit);
    // The list as wide as its columns: no name cut (a long state wraps).
    void fitColumns();
    void updateTitle();
    void saveAs();
    void writeReport();
    void addDevice();
    QTreeWidgetItem* rowOf(const MachineUnit* unit) const;

    Machine* m_machine;
    QTreeWidget* m_list;
    QStackedWidget* m_stack;
    QMenu* m_machineMenu = nullptr;
    QString m_lastMessage;
};

}  // namespace cambench
