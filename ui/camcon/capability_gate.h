#pragma once

#include "ui/camcon/camcon_section_page.h"

#include "comm/camcon/camcon_device.h"

class QLabel;
class QListWidgetItem;
class QStackedWidget;

namespace cambench {

class DeviceSession;

// A section that needs a capability of the connected protocol (users,
// EEPROM backup, dead-time modes, ...). Whenever a connection is made it
// asks the device: with the capability it shows its page (and, when the
// window reads everything, lets the page read), without it a page that says
// why (the protocol's own reason, translated) and greys its entry in the
// navigation, so that nothing of another protocol's device stays on view.
// Offline, the page is shown for editing.
class CapabilityGate : public CamConSectionPage {
    Q_OBJECT
public:
    CapabilityGate(DeviceSession* session, CamConSectionPage* page,
                   comm::CamConCapability capability, QWidget* parent = nullptr);

    QString sectionTitle() const override { return m_page->sectionTitle(); }
    QList<SectionDifference> differences() const override;
    void deviceConnected() override;

    CamConSectionPage* page() const { return m_page; }
    bool isAvailable() const { return m_available; }
    // Why the section is not available (translated), empty while it is.
    QString reason() const;
    // The navigation entry of this section, greyed while not available.
    void setNavItem(QListWidgetItem* item) override;

Q_SIGNALS:
    void availabilityChanged(bool available);

private:
    // Asks the connected device; `thenRead`: the page reads when available.
    void checkAvailability(bool thenRead);
    void showAvailability(bool available, const QString& reason);

    DeviceSession* m_session;
    CamConSectionPage* m_page;
    comm::CamConCapability m_capability;
    QStackedWidget* m_stack;
    QLabel* m_reason;
    QListWidgetItem* m_item = nullptr;
    bool m_available = true;
};

}  // namespace cambench
