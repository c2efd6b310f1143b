#pragma once

#include "device_writer.h"
#include "ui/camcon/camcon_section_page.h"

#include "model/camcon/device_info.h"

namespace cambench {

class CamEditorWidget;
class TimingBar;
class DeviceSession;
class Workspace;

// The cam program editor (ui/cameditor) wired to the device: its read and
// write requests become jobs, and the monitor's live position and outputs
// reach its diagram while they are live.
class CamPage : public CamConSectionPage {
    Q_OBJECT
public:
    CamPage(DeviceSession* session, Workspace* workspace, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Cam programs"); }
    QList<SectionDifference> differences() const override;

    CamEditorWidget* editor() const { return m_editor; }
    TimingBar* timingBar() const { return m_timing; }

    void readProgram(int program, std::function<void(const Status&)> done = {});
    // Writes what differs in `program` (a program never read: all of it).
    void writeProgram(int program, std::function<void(const WriteResult&)> done = {});
    void showStatus(const DeviceStatus& status);
    void clearLive();

private:
    DeviceSession* m_session;
    Workspace* m_workspace;
    CamEditorWidget* m_editor;
    TimingBar* m_timing;
};

}  // namespace cambench
