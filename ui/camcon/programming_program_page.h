#pragma once

#include "ui/camcon/camcon_section_page.h"

#include "model/camcon/programming_program.h"

class QComboBox;
class QLabel;
class QSpinBox;

#include <optional>

namespace cambench {

class DeviceSession;
class Workspace;

// The programming program of the table interface (area 201 words 70..73):
// the program whose cams the table's areas 1..200 read and write, and how
// the device changes to it. The values live in the workspace
// (Workspace::programmingProgram), so a project saves them and Compare lists them.
class ProgrammingProgramPage : public CamConSectionPage {
    Q_OBJECT
public:
    ProgrammingProgramPage(DeviceSession* session, Workspace* workspace, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Programming program"); }
    QList<SectionDifference> differences() const override;
    int itemCount() const override { return 1; }
    void deviceConnected() override { readFromDevice(); }

    void readFromDevice();
    // Through the one write path, like every section.
    void writeToDevice(std::function<void(const WriteResult&)> done = {});
    ProgrammingProgram edited() const;
    void setEdited(const ProgrammingProgram& programming);

private:
    // The fields changed: their values become the workspace's edit.
    void takeFields();
    // Shows the workspace's values (a project opened, a write's outcome).
    void showCopies();
    // Marks the fields that differ from the device and says whether the
    // values are read.
    void refreshMarks();

    DeviceSession* m_session;
    Workspace* m_workspace;
    QSpinBox* m_program;
    QComboBox* m_mode;
    QSpinBox* m_switchValue;
    QLabel* m_problems;
    QLabel* m_state;
};

}  // namespace cambench
