#pragma once

#include "ui/camcon/camcon_section_page.h"

#include "comm/camcon/table/short_commands.h"
#include "comm/usecases/item_outcome.h"

#include <functional>

class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace cambench {

namespace comm::table {
class ShortClient;
}
class DeviceSession;
class Workspace;

// The S7-CP340 coupling (issue 12, point 5): sends the telegrams the PLC's
// function block sends (short commands 0x01..0x07 on the table interface),
// shows the answers laid out as the data block areas of the coupling
// manual (status, cam table, dead times) and says in words what a PLC
// program would see. When the coupling does not work, this tells whether the
// CamCon answers as it should - then the PLC program is at fault.
// Writes ask first, saying what will switch, and report what the device
// holds afterwards (comm/usecases/short_coupling.h).
class PlcCouplingPage : public CamConSectionPage {
    Q_OBJECT
public:
    PlcCouplingPage(DeviceSession* session, Workspace* workspace, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("PLC coupling"); }

    void readStatus();
    void resetErrors();
    void changeProgram(int program);
    void readTrack();
    void writeTrack();
    void readDeadTime();
    void writeDeadTime();

    // What the page shows, for tests and the screenshot tour.
    QString statusInWords() const;
    QString lastOutcome() const;
    QSpinBox* programBox() const { return m_program; }
    QSpinBox* outputBox() const { return m_output; }
    QTableWidget* camTable() const { return m_cams; }
    QDoubleSpinBox* deadTimeBox() const { return m_deadTime; }

private:
    void showStatus(const comm::table::ShortStatus& status);
    // `sayWhatWasRead`: a read of its own, not the check after a write.
    void readTrackOf(int program, int output, bool sayWhatWasRead);
    void readDeadTimeOf(int output);
    void showTrack(const Track& track);
    void showOutcome(const usecases::OutcomeLine& line);
    void showFailure(const QString& what, const Error& error);
    bool confirmed(const QString& question);
    // Runs one checked short write on the worker, shows its outcome and
    // then `readBack` (the matching query), so that what the page shows is
    // what the device holds.
    void runCheckedWrite(const QString& title,
                         std::function<usecases::OutcomeLine(comm::table::ShortClient&)> write,
                         std::function<void()> readBack);
    Track trackInTable() const;

    DeviceSession* m_session;
    Workspace* m_workspace;  // its device copies learn what these telegrams read
    QLabel* m_statusArea;
    QLabel* m_statusWords;
    QSpinBox* m_program;
    QSpinBox* m_output;
    QTableWidget* m_cams;
    QDoubleSpinBox* m_deadTime;
    QLabel* m_deadTimeArea;
    QLabel* m_outcome;
};

}  // namespace cambench
