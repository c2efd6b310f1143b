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
    int itemCount() const override { return int(m_device.size()); }
    void writeChanges(std::function<void(const WriteResult&)> done = {});
    void deviceConnected() override { readFromDevice(); }

    void readFromDevice();
    QTableWidget* table() const { return m_table; }
    // The values shown for `output` (1-based), as edited.
    OutputDeadTime edited(int output) const;
    void setEdited(int output, const OutputDeadTime& deadTime);
    const DeadTimeModes& onDevice() const { return m_device; }

private:
    void showModes(const DeadTimeModes& modes);
    // Marks every edited cell and output and tells the workspace how many
    // outputs differ from the device.
    void refreshEdits();
    // Modes from a project file become edits of the rows shown (or of the
    // rows once the device is read); a device's become the page's copy.
    void takeIncoming(const DeadTimeModes& modes, bool fromDevice);
    int rowOf(int output) const;  // -1 when the output is not shown

    DeviceSession* m_session;
    Workspace* m_workspace;
    QTableWidget* m_table;
    QLabel* m_note;
    DeadTimeModes m_device;   // as last read or written
    DeadTimeModes m_pending;  // from a project file, waiting for the device's rows
};

}  // namespace cambench
