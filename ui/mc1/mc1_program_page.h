#pragma once

#include "mc1_page.h"

class QLabel;
class QPushButton;

namespace cambench {

// Program: the PLC program's status (table 39 decoded, program counter),
// live while shown; start, stop, step, reset and flash save/load, each
// after a confirmation that says what it does (MC200 V2).
class Mc1ProgramPage : public Mc1Page {
    Q_OBJECT
public:
    explicit Mc1ProgramPage(DeviceSession* session, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Program"); }
    bool poll() override;

    QLabel* statusLabel() const { return m_status; }
    // Asks (with what it does), then sends `command` and shows the status after.
    void run(comm::Mc1ProgramCommand command);

protected:
    void factsChanged() override;

private:
    void showStatus(const comm::Mc1ProgramStatus& status);

    QLabel* m_availability;
    QLabel* m_status;
    QLabel* m_flags;
    QList<QPushButton*> m_buttons;
};

}  // namespace cambench
