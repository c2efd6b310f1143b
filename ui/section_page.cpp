#include "section_page.h"

namespace cambench {

void SectionPage::writeDifferences(DeviceSession* session, Workspace* workspace,
                                   std::function<void(const WriteResult&)> done) {
    QList<WorkspaceItem> items;
    for (const SectionDifference& difference : differences()) items << difference.item;
    const QString title = sectionTitle();
    if (items.isEmpty()) {
        Q_EMIT statusMessage(tr("%1: nothing to write, the device holds what you see.").arg(title));
        return;
    }
    Q_EMIT statusMessage(tr("%1: writing…").arg(title));
    writeToDevice(this, session, workspace, items, [this, title, done](const WriteResult& result) {
        Q_EMIT statusMessage(tr("%1: %2").arg(title, writeSummary(result)));
        presentWriteResult(this, title, result);
        if (done) done(result);
    });
}

}  // namespace cambench
