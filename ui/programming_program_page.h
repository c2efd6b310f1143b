#pragma once

#include "section_page.h"

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
// the device changes to it.
class ProgrammingProgramPage : public SectionPage {
    Q_OBJECT
public:
    ProgrammingProgramPage(DeviceSession* session, Workspace* workspace, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Programming program"); }
    void deviceConnected() override { readFromDevice(); }

    void readFromDevice();
    void writeToDevice();
    ProgrammingProgram edited() const;
    void setEdited(const ProgrammingProgram& programming);

private:
    // Marks the fields that differ from the device, says whether the values
    // are read, and tells the workspace whether there is an edit.
    void refreshEdits();

    DeviceSession* m_session;
    Workspace* m_workspace;
    QSpinBox* m_program;
    QComboBox* m_mode;
    QSpinBox* m_switchValue;
    QLabel* m_problems;
    QLabel* m_state;
    std::optional<ProgrammingProgram> m_device;  // as last read or written
};

}  // namespace cambench
