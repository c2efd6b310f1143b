#pragma once

#include <QWidget>

class QListWidgetItem;

namespace cambench {

// A page of the main window: one section of a device, or the shell's own
// connection page. A family's pages that hold data derive from its own
// page class (the CamCon's: CamConSectionPage) for what Compare and Write
// need.
class SectionPage : public QWidget {
    Q_OBJECT
public:
    using QWidget::QWidget;

    virtual QString sectionTitle() const = 0;
    // The sections outside the whole-device read (those only some protocols
    // have) read here once the device's identity is known.
    virtual void deviceConnected() {}
    // The page's entry in the window's list, for a page that greys or
    // explains its entry itself.
    virtual void setNavItem(QListWidgetItem* item) { Q_UNUSED(item); }

Q_SIGNALS:
    void statusMessage(const QString& text);
};

}  // namespace cambench
