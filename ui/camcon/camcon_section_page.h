#pragma once

#include "model/camcon/workspace_item.h"
#include "ui/camcon/device_writer.h"
#include "ui/section_page.h"

#include "model/result.h"

#include <functional>

class QHBoxLayout;

namespace cambench {

class DeviceSession;
class Workspace;

// One line of "Compare with device": an item whose edited value differs
// from the device's.
struct SectionDifference {
    WorkspaceItem item;
    QString label;
    QString device;
    QString edited;
};

// A page of one CamCon section. Pages that hold data list where the edited
// values differ from the device; writing goes through writeToDevice()
// (device_writer.h), reading through DeviceReader.
class CamConSectionPage : public SectionPage {
    Q_OBJECT
public:
    using SectionPage::SectionPage;

    virtual QList<SectionDifference> differences() const { return {}; }
    // How many items the section holds for the device: a write reports
    // the ones it did not send as already on the device.
    virtual int itemCount() const { return int(differences().size()); }

protected:
    // The bar at the top of a section page, the same on every page:
    // `before` (what the read is of: an output, a network), the read button
    // ("Read from device" unless `readText` says otherwise), "Write
    // changes" where the page writes with it, the page's own `actions`, a
    // stretch, then `right` (a note, the limits).
    struct ReadWriteBar {
        // `write` empty: no "Write changes".
        ReadWriteBar(std::function<void()> read, std::function<void()> write)
            : read(std::move(read)), write(std::move(write)) {}
        std::function<void()> read;
        std::function<void()> write;
        QString readText;
        QList<QWidget*> before;
        QList<QWidget*> actions;
        QList<QWidget*> right;
    };
    QHBoxLayout* readWriteBar(const ReadWriteBar& bar);

    // What a page's read says in the status bar: `reading` now, then
    // `done()` once the values came, the reason when the person kept the
    // edits (the read was not taken), or `failed` with why (%1). Given to
    // a devicereads function as its `done`.
    std::function<void(const Status&)> reportRead(const QString& reading,
                                                  std::function<QString()> done,
                                                  const QString& failed);

    // "Write changes" of a page: every difference of this section through
    // the one write path; the summary in the status bar, the items not
    // written in a dialog; then `done`.
    void writeDifferences(DeviceSession* session, Workspace* workspace,
                          std::function<void(const WriteResult&)> done = {});
};

}  // namespace cambench
