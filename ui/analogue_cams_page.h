#pragma once

#include "page_write_report.h"
#include "section_page.h"

#include "model/camcon/analogue_cams.h"

class QLabel;
class QSpinBox;
class QTableWidget;

namespace cambench {

class DeviceSession;
class Workspace;

// Analogue cams (table interface, areas 241..254): the base points of one
// analogue output, a value at each position. Read, edit, write.
class AnalogueCamsPage : public SectionPage {
    Q_OBJECT
public:
    AnalogueCamsPage(DeviceSession* session, Workspace* workspace, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Analogue cams"); }
    // What is edited and differs from the device (not in Compare with device).
    QList<PageChange> changes() const;
    void writeItems(const QStringList& keys, std::function<void(const PageWriteReport&)> done);
    void deviceConnected() override { readFromDevice(); }

    void readFromDevice();
    QSpinBox* outputChooser() const { return m_output; }
    QTableWidget* table() const { return m_table; }
    // The points shown, as edited.
    AnalogueCamTrack edited() const;
    void setEdited(const AnalogueCamTrack& track);
    const AnalogueCamTrack& onDevice() const { return m_device; }

private:
    // Marks the edited points and tells the workspace whether the output
    // shown differs from the device.
    void refreshEdits();

    DeviceSession* m_session;
    Workspace* m_workspace;
    QSpinBox* m_output;
    QTableWidget* m_table;
    QLabel* m_problems;
    AnalogueCamTrack m_device;  // of the output shown, as last read or written
};

}  // namespace cambench
