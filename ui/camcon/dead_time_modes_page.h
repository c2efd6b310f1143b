#pragma once

#include "ui/camcon/camcon_section_page.h"

#include "model/camcon/dead_time_modes.h"

class QLabel;
class QTableWidget;

namespace cambench {

class DeviceSession;
class Workspace;

// Dead-time modes and the separate switch-on and switch-off dead times of
// each output (table interface, areas 1..200 words 251..253): read, edit,
// write the outputs that differ from the device.
class DeadTimeModesPage : public CamConSectionPage {
    Q_OBJECT
public:
    enum Column { OutputColumn, ModeColumn, NormalColumn, OnColumn, OffColumn, COUNT };

    DeadTimeModesPage(DeviceSession* session, Workspace* workspace, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Dead-time modes"); }
    // What is edited and differs from the device, for Compare with device;
    // written through the one write path like every section.
    QList<SectionDifference> differences() const override;
    int itemCount() const override { return int(onDevice().size()); }
    void writeChanges(std::function<void(const WriteResult&)> done = {});
    void deviceConnected() override { readFromDevice(); }

    void readFromDevice();
    QTableWidget* table() const { return m_table; }
    // The values shown for `output` (1-based), as edited.
    OutputDeadTime edited(int output) const;
    // An edit of an output the device has (as typing into its row does).
    void setEdited(int output, const OutputDeadTime& deadTime);
    DeadTimeModes onDevice() const;

private:
    // The table is a view of the workspace's section: a row for each output
    // the device has, showing the values as edited, edits marked.
    void showModes();
    void markEdits();
    // A cell or mode changed: the row's values become the output's edit.
    void takeRow(int row);
    void fillRow(int row, const OutputDeadTime& deadTime);
    int rowOf(int output) const;      // -1 when the output is not shown
    QList<int> shownOutputs() const;  // in the order of the rows

    DeviceSession* m_session;
    Workspace* m_workspace;
    QTableWidget* m_table;
    QLabel* m_note;
};

}  // namespace cambench
