#include "camcon_section_page.h"

#include "ui/sentence.h"

namespace cambench {

void CamConSectionPage::writeDifferences(DeviceSession* session, Workspace* workspace,
                                         std::function<void(const WriteResult&)> done) {
    QList<WorkspaceItem> items;
    for (const SectionDifference& difference : differences()) items << difference.item;
    const QString title = sectionTitle();
    if (items.isEmpty()) {
        Q_EMIT statusMessage(tr("%1: nothing to write, the device holds what you see.").arg(title));
        return;
    }
    Q_EMIT statusMessage(tr("%1: writing…").arg(title));
    const int others = std::max(0, itemCount() - int(items.size()));
    writeToDevice(
        this, session, workspace, items, [this, title, others, done](const WriteResult& result) {
            QString summary = tr("%1: %2").arg(title, writeSummary(result));
            if (result && others > 0)
                summary = asSentence(summary) + QLatin1Char(' ') +
                          tr("%n other item(s) of this section were already as on the device "
                             "and not sent.",
                             nullptr, others);
            Q_EMIT statusMessage(summary);
            presentWriteResult(this, title, result);
            if (done) done(result);
        });
}

}  // namespace cambench
