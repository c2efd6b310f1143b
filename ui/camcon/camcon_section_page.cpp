#include "camcon_section_page.h"

#include "ui/sentence.h"

#include <QHBoxLayout>
#include <QPointer>
#include <QPushButton>

namespace cambench {

QHBoxLayout* CamConSectionPage::readWriteBar(const ReadWriteBar& bar) {
    auto* layout = new QHBoxLayout;
    for (QWidget* widget : bar.before) layout->addWidget(widget);
    auto* read =
        new QPushButton(bar.readText.isEmpty() ? tr("Read from device") : bar.readText, this);
    connect(read, &QPushButton::clicked, this, bar.read);
    layout->addWidget(read);
    if (bar.write) {
        auto* write = new QPushButton(tr("Write changes"), this);
        connect(write, &QPushButton::clicked, this, bar.write);
        layout->addWidget(write);
    }
    for (QWidget* widget : bar.actions) layout->addWidget(widget);
    layout->addStretch();
    for (QWidget* widget : bar.right) layout->addWidget(widget);
    return layout;
}

std::function<void(const Status&)> CamConSectionPage::reportRead(const QString& reading,
                                                                 std::function<QString()> done,
                                                                 const QString& failed) {
    Q_EMIT statusMessage(reading);
    QPointer<CamConSectionPage> page(this);
    return [page, done = std::move(done), failed](const Status& status) {
        if (!page) return;
        if (status)
            Q_EMIT page->statusMessage(done());
        else if (status.error().kind == ErrorKind::Cancelled)
            Q_EMIT page->statusMessage(status.error().message);
        else
            Q_EMIT page->statusMessage(failed.arg(status.error().message));
    };
}

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
    writeToDevice(this, session, workspace, items,
                  [this, session, title, others, done](const WriteResult& result) {
                      QString summary = tr("%1: %2").arg(title, writeSummary(result));
                      if (result && others > 0)
                          summary =
                              asSentence(summary) + QLatin1Char(' ') +
                              tr("%n other item(s) of this section were already as on the device "
                                 "and not sent.",
                                 nullptr, others);
                      Q_EMIT statusMessage(summary);
                      presentWriteResult(this, session, title, result);
                      if (done) done(result);
                  });
}

}  // namespace cambench
