#pragma once

#include "ui/camcon/device_writer.h"
#include "ui/camcon/workspace_item.h"
#include "ui/section_page.h"

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
    // "Write changes" of a page: every difference of this section through
    // the one write path; the summary in the status bar, the items not
    // written in a dialog; then `done`.
    void writeDifferences(DeviceSession* session, Workspace* workspace,
                          std::function<void(const WriteResult&)> done = {});
};

}  // namespace cambench
