#pragma once

#include "ui/camcon/camcon_section_page.h"

#include "model/camcon/analogue_cams.h"

class QLabel;
class QSpinBox;
class QTableWidget;

namespace cambench {

class DeviceSession;
class Workspace;

// Analogue cams (table interface, areas 241..254): the base points of one
// analogue output at a time, a value at each position. The values live in
// the workspace (Workspace::analogueCams): edits of every output stay when
// another one is shown, are saved with the project, listed in Compare with
// device and written through the one write path.
class AnalogueCamsPage : public CamConSectionPage {
    Q_OBJECT
public:
    AnalogueCamsPage(DeviceSession* session, Workspace* workspace, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Analogue cams"); }
    QList<SectionDifference> differences() const override;
    int itemCount() const override { return kAnalogueOutputs; }
    void deviceConnected() override { readFromDevice(); }

    // Reads the output shown; the device's points replace its edit.
    void readFromDevice();
    // Every edited output through the one write path.
    void writeChanges(std::function<void(const WriteResult&)> done = {});
    QTableWidget* table() const { return m_table; }
    // The points shown, as edited.
    AnalogueCamTrack edited() const;
    void setEdited(const AnalogueCamTrack& track);
    // The device's points of the output shown (empty track when not read).
    AnalogueCamTrack onDevice() const;

private:
    // Shows the workspace's points of the output chosen.
    void showOutput();
    // The table changed: its points become the output's edit.
    void takeTable();
    // Marks the points that differ from the device and says what is wrong.
    void refreshMarks();

    DeviceSession* m_session;
    Workspace* m_workspace;
    QSpinBox* m_output;
    QTableWidget* m_table;
    QLabel* m_state;
    QLabel* m_problems;
};

}  // namespace cambench
