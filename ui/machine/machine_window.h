#pragma once

#include <QMainWindow>

class QStackedWidget;
class QTreeWidget;
class QTreeWidgetItem;

namespace cambench {

class Machine;
class MachineUnit;

// The window of a machine: the list of its devices (name, family, port, a
// lamp with the line's state in words, the edits not written) beside the
// selected device's own window of pages, its menus and its STOP (the
// machine's: it stops every device). The STOP key works from every widget
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
    void addRow(MachineUnit* unit);
    void updateRow(MachineUnit* unit);
    void updateTitle();
    void saveAs();
    void writeReport();
    void addDevice();
    QTreeWidgetItem* rowOf(const MachineUnit* unit) const;

    Machine* m_machine;
    QTreeWidget* m_list;
    QStackedWidget* m_stack;
    QString m_lastMessage;
};

}  // namespace cambench
