#include "capability_gate.h"
#include "ui/camcon/camcon_jobs.h"

#include "ui/device_session.h"

#include <QLabel>
#include <QListWidgetItem>
#include <QPalette>
#include <QStackedWidget>
#include <QVBoxLayout>

namespace cambench {

namespace {

struct Availability {
    bool available = true;
    QString reason;
};

}  // namespace

CapabilityGate::CapabilityGate(DeviceSession* session, CamConSectionPage* page,
                               comm::CamConCapability capability, QWidget* parent)
    : CamConSectionPage(parent),
      m_session(session),
      m_page(page),
      m_capability(capability),
      m_stack(new QStackedWidget),
      m_reason(new QLabel) {
    auto* missing = new QWidget;
    auto* missingLayout = new QVBoxLayout(missing);
    auto* headline = new QLabel(tr("<b>Not available with the connected protocol</b>"));
    m_reason->setWordWrap(true);
    m_reason->setTextInteractionFlags(Qt::TextSelectableByMouse);
    missingLayout->addWidget(headline);
    missingLayout->addWidget(m_reason);
    missingLayout->addStretch();
    m_stack->addWidget(m_page);
    m_stack->addWidget(missing);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_stack);
    connect(m_page, &SectionPage::statusMessage, this, &SectionPage::statusMessage);
    connect(m_session, &DeviceSession::stateChanged, this, [this](comm::ConnectionState state) {
        if (state == comm::ConnectionState::Connected) checkAvailability(false);
    });
    // A window rebuilt on a language switch while connected asks at once:
    // no section of a protocol that lacks it may look available meanwhile.
    if (m_session->isOnline()) checkAvailability(false);
}

QList<SectionDifference> CapabilityGate::differences() const {
    return m_available ? m_page->differences() : QList<SectionDifference>{};
}

void CapabilityGate::deviceConnected() {
    checkAvailability(true);
}

void CapabilityGate::checkAvailability(bool thenRead) {
    const comm::CamConCapability capability = m_capability;
    runOnCamCon<Availability>(
        m_session, this, tr("Check what the protocol offers"),
        [capability](comm::CamConDevice& device, comm::JobContext&) -> Result<Availability> {
            return Availability{device.has(capability), device.lacks(capability)};
        },
        [this, thenRead](Result<Availability> availability) {
            if (!availability) return;
            showAvailability(availability->available, availability->reason);
            if (availability->available && thenRead) m_page->deviceConnected();
        });
}

QString CapabilityGate::reason() const {
    return m_available ? QString() : m_reason->text();
}

void CapabilityGate::setNavItem(QListWidgetItem* item) {
    m_item = item;
    showAvailability(m_available, m_reason->text());
}

void CapabilityGate::showAvailability(bool available, const QString& reason) {
    const bool changed = available != m_available;
    m_available = available;
    // The protocol's own reason, translated where it is made (CamConDevice::lacks()).
    m_reason->setText(available ? QString() : reason);
    m_stack->setCurrentIndex(available ? 0 : 1);
    if (m_item) {
        m_item->setForeground(
            palette().brush(available ? QPalette::Active : QPalette::Disabled, QPalette::Text));
        m_item->setToolTip(m_reason->text());
    }
    if (changed) Q_EMIT availabilityChanged(available);
}

}  // namespace cambench
