#pragma once

#include "section_page.h"

#include <optional>

class QLabel;
class QPushButton;

namespace cambench {

class DeviceSession;

// The EEPROM lock of the table interface (area 205 word 4): while the
// EEPROM is locked every change written is kept in RAM only and is lost
// when the device is switched off. The page says so plainly.
class EepromLockPage : public SectionPage {
    Q_OBJECT
public:
    explicit EepromLockPage(DeviceSession* session, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("EEPROM lock"); }
    void deviceConnected() override { readFromDevice(); }

    void readFromDevice();
    void setLocked(bool locked);
    // As last read or written; unset before the first read.
    std::optional<bool> locked() const { return m_locked; }
    QString warningText() const;
    bool warningShown() const;

Q_SIGNALS:
    void lockChanged(bool locked);

private:
    void showLock(std::optional<bool> locked);

    DeviceSession* m_session;
    QLabel* m_state;
    QLabel* m_warning;
    QPushButton* m_lock;
    QPushButton* m_unlock;
    std::optional<bool> m_locked;
};

}  // namespace cambench
