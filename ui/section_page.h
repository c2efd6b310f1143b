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
    // Another device (of this family or another) came on the line: what
    // the page says of the device before - results, compared files, its
    // identity - goes, so that nothing of it is shown as the new one's.
    virtual void forgetDevice() {}
    // The page's entry in the window's list, for a page that greys or
    // explains its entry itself.
    virtual void setNavItem(QListWidgetItem* item) { Q_UNUSED(item); }

Q_SIGNALS:
    void statusMessage(const QString& text);
};

}  // namespace cambench
