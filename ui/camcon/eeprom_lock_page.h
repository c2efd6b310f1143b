#pragma once

#include "ui/camcon/camcon_section_page.h"

#include <optional>

class QLabel;
class QPushButton;

namespace cambench {

class DeviceSession;
class Workspace;

// The EEPROM lock of the table interface (area 205 word 4): while the
// EEPROM is locked every change written is kept in RAM only and is lost
// when the device is switched off. The page says so plainly. The state
// lives in the workspace (Workspace::eepromLock): a project carries it, and a
// project that wants another state shows here and in Compare as an edit.
class EepromLockPage : public CamConSectionPage {
    Q_OBJECT
public:
    EepromLockPage(DeviceSession* session, Workspace* workspace, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("EEPROM lock"); }
    QList<SectionDifference> differences() const override;
    int itemCount() const override { return 1; }
    void deviceConnected() override { readFromDevice(); }

    void readFromDevice();
    // Locks or unlocks through the one write path, read back.
    void setLocked(bool locked);
    // As last read or written; unset before the first read.
    std::optional<bool> locked() const;
    QString warningText() const;
    bool warningShown() const;

private:
    void showLock();

    DeviceSession* m_session;
    Workspace* m_workspace;
    QLabel* m_state;
    QLabel* m_wanted;
    QLabel* m_warning;
    QPushButton* m_lock;
    QPushButton* m_unlock;
};

}  // namespace cambench
