#include "eeprom_lock_page.h"
#include "ui/camcon/camcon_jobs.h"

#include "ui/change_marker.h"
#include "ui/device_session.h"
#include "workspace.h"

#include "comm/camcon/usecases/value_text.h"

#include <QDateTime>

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace cambench {

EepromLockPage::EepromLockPage(DeviceSession* session, Workspace* workspace, QWidget* parent)
    : CamConSectionPage(parent),
      m_session(session),
      m_workspace(workspace),
      m_state(new QLabel),
      m_wanted(new QLabel),
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
    m_wanted->setWordWrap(true);
    // Lock and Unlock write at once: no "Write changes".
    ReadWriteBar bar([this] { readFromDevice(); }, {});
    bar.actions = {m_lock, m_unlock};
    QHBoxLayout* buttons = readWriteBar(bar);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addWidget(m_state);
    layout->addWidget(m_wanted);
    layout->addWidget(m_warning);
    layout->addLayout(buttons);
    layout->addStretch();
    connect(m_lock, &QPushButton::clicked, this, [this] { setLocked(true); });
    connect(m_unlock, &QPushButton::clicked, this, [this] { setLocked(false); });
    connect(m_workspace, &Workspace::tableSectionsChanged, this, &EepromLockPage::showLock);
    connect(m_session, &DeviceSession::stateChanged, this, &EepromLockPage::showLock);
    showLock();
}

void EepromLockPage::readFromDevice() {
    runOnCamCon<bool>(
        m_session, this, tr("Read the EEPROM lock"),
        [](comm::CamConDevice& device, comm::JobContext&) { return device.readEepromLock(); },
        [this](Result<bool> locked) {
            if (!locked) {
                // Unknown is not "unlocked": the copy stays as it was.
                Q_EMIT statusMessage(
                    tr("Reading the EEPROM lock failed: %1").arg(locked.error().message));
                return;
            }
            m_workspace->eepromLock().setDevice(*locked);
            m_workspace->setReadTime(ProjectPart::EepromLock, QDateTime::currentDateTimeUtc());
        });
}

void EepromLockPage::setLocked(bool locked) {
    m_workspace->eepromLock().edit(locked);
    const QString title = locked ? tr("Lock the EEPROM") : tr("Unlock the EEPROM");
    // What the device holds afterwards comes from the write's read-back.
    writeToDevice(this, m_session, m_workspace, {WorkspaceItem::eepromLock()},
                  [this, title](const WriteResult& result) {
                      QString text = tr("%1: %2").arg(title, writeSummary(result));
                      // Locked now: what is written from here on is not kept.
                      if (this->locked().value_or(false))
                          text += QLatin1Char(' ') + m_warning->text();
                      Q_EMIT statusMessage(text);
                      presentWriteResult(this, m_session, title, result);
                  });
}

std::optional<bool> EepromLockPage::locked() const {
    return m_workspace->eepromLock().deviceValue();
}

QString EepromLockPage::warningText() const {
    return m_warning->text();
}

bool EepromLockPage::warningShown() const {
    return !m_warning->isHidden();
}

void EepromLockPage::showLock() {
    const std::optional<bool> locked = m_workspace->eepromLock().deviceValue();
    if (!locked) {
        m_state->setText(tr("State of the EEPROM lock: not read"));
    } else if (*locked) {
        m_state->setText(tr("The EEPROM is locked."));
    } else {
        m_state->setText(tr("The EEPROM is not locked: changes are stored permanently."));
    }
    m_wanted->setVisible(m_workspace->eepromLock().isChanged());
    if (m_workspace->eepromLock().isChanged()) {
        m_wanted->setText(changedMarker() +
                          (*m_workspace->eepromLock().value()
                               ? tr("The project wants the EEPROM locked; not written yet.")
                               : tr("The project wants the EEPROM unlocked; not written yet.")));
    }
    m_warning->setText(
        tr("Changes written now are kept in RAM only. They are lost when the "
           "device is switched off. Unlock the EEPROM to keep them."));
    m_warning->setVisible(locked.value_or(false));
    m_lock->setEnabled(m_session->isOnline() && !locked.value_or(false));
    m_unlock->setEnabled(m_session->isOnline() && locked.value_or(true));
}

QList<SectionDifference> EepromLockPage::differences() const {
    if (!m_workspace->eepromLock().isChanged()) return {};
    const std::optional<bool>& device = m_workspace->eepromLock().deviceValue();
    return {{WorkspaceItem::eepromLock(), sectionTitle(),
             device ? usecases::eepromLockText(*device) : tr("not read"),
             usecases::eepromLockText(*m_workspace->eepromLock().value())}};
}

}  // namespace cambench
