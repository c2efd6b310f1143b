#include "eeprom_lock_page.h"

#include "device_session.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace cambench {

EepromLockPage::EepromLockPage(DeviceSession* session, QWidget* parent)
    : SectionPage(parent),
      m_session(session),
      m_state(new QLabel),
      m_warning(new QLabel),
      m_lock(new QPushButton(tr("Lock the EEPROM"))),
      m_unlock(new QPushButton(tr("Unlock the EEPROM"))) {
    auto* intro = new QLabel(
        tr("Writing the same values again and again (from a PLC, every cycle) wears the "
           "device's EEPROM out. Lock it first: changes then stay in RAM only. A complete "
           "deletion of the device unlocks it."));
    intro->setWordWrap(true);
    m_warning->setWordWrap(true);
    m_warning->setStyleSheet(QStringLiteral("QLabel { color: #b03a2e; font-weight: bold; }"));
    auto* read = new QPushButton(tr("Read from device"));
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(read);
    buttons->addWidget(m_lock);
    buttons->addWidget(m_unlock);
    buttons->addStretch();
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addWidget(m_state);
    layout->addWidget(m_warning);
    layout->addLayout(buttons);
    layout->addStretch();
    connect(read, &QPushButton::clicked, this, &EepromLockPage::readFromDevice);
    connect(m_lock, &QPushButton::clicked, this, [this] { setLocked(true); });
    connect(m_unlock, &QPushButton::clicked, this, [this] { setLocked(false); });
    showLock(std::nullopt);
}

void EepromLockPage::readFromDevice() {
    m_session->run<bool>(
        this, tr("Read the EEPROM lock"),
        [](comm::CamConDevice& device, comm::JobContext&) { return device.readEepromLock(); },
        [this](Result<bool> locked) {
            if (!locked) {
                // Unknown is not "unlocked": say that nothing is known.
                showLock(std::nullopt);
                Q_EMIT statusMessage(
                    tr("Reading the EEPROM lock failed: %1").arg(locked.error().message));
                return;
            }
            showLock(locked.value());
        });
}

void EepromLockPage::setLocked(bool locked) {
    m_session->run<bool>(
        this, locked ? tr("Lock the EEPROM") : tr("Unlock the EEPROM"),
        [locked](comm::CamConDevice& device, comm::JobContext&) -> Result<bool> {
            const Status written = device.writeEepromLock(locked);
            if (!written) return written.error();
            // What the device holds now, not what was asked for.
            return device.readEepromLock();
        },
        [this](Result<bool> now) {
            if (!now) {
                showLock(std::nullopt);
                Q_EMIT statusMessage(tr("The EEPROM lock could not be changed: %1; its state is "
                                        "unknown, read it again.")
                                         .arg(now.error().message));
                return;
            }
            showLock(now.value());
        });
}

QString EepromLockPage::warningText() const {
    return m_warning->text();
}

bool EepromLockPage::warningShown() const {
    return !m_warning->isHidden();
}

void EepromLockPage::showLock(std::optional<bool> locked) {
    const bool changed = locked != m_locked;
    m_locked = locked;
    if (!locked) {
        m_state->setText(tr("State of the EEPROM lock: not read"));
    } else if (*locked) {
        m_state->setText(tr("The EEPROM is locked."));
    } else {
        m_state->setText(tr("The EEPROM is not locked: changes are stored permanently."));
    }
    m_warning->setText(
        tr("Changes written now are kept in RAM only. They are lost when the "
           "device is switched off. Unlock the EEPROM to keep them."));
    m_warning->setVisible(locked.value_or(false));
    m_lock->setEnabled(locked.has_value() && !*locked);
    m_unlock->setEnabled(locked.value_or(false));
    if (changed && locked) Q_EMIT lockChanged(*locked);
    if (locked.value_or(false)) Q_EMIT statusMessage(m_warning->text());
}

}  // namespace cambench
