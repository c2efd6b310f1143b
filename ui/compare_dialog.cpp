#include "compare_dialog.h"

#include "section_page.h"

#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QPointer>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace cambench {

namespace {
constexpr int kKeyRole = Qt::UserRole;
constexpr int kPageRole = Qt::UserRole + 1;
}  // namespace

CompareDialog::CompareDialog(const QList<SectionPage*>& pages, QWidget* parent)
    : QDialog(parent), m_pages(pages), m_tree(new QTreeWidget), m_report(new QLabel) {
    setWindowTitle(tr("Compare with device"));
    m_tree->setColumnCount(3);
    m_tree->setHeaderLabels({tr("Item"), tr("On the device"), tr("Edited on this PC")});
    m_tree->header()->setSectionResizeMode(QHeaderView::Interactive);
    m_tree->setColumnWidth(0, 280);
    m_tree->setColumnWidth(1, 360);
    m_tree->setWordWrap(true);
    m_report->setWordWrap(true);
    m_report->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    m_writeChecked = buttons->addButton(tr("Write selected"), QDialogButtonBox::ActionRole);
    m_writeAll = buttons->addButton(tr("Write all"), QDialogButtonBox::ActionRole);
    auto* refreshButton = buttons->addButton(tr("Refresh"), QDialogButtonBox::ResetRole);

    auto* layout = new QVBoxLayout(this);
    auto* intro = new QLabel(tr("Items edited on this PC that differ from the device. Check the ones "
                                "to write, or write all."));
    intro->setWordWrap(true);
    layout->addWidget(intro);
    layout->addWidget(m_tree, 1);
    layout->addWidget(m_report);
    layout->addWidget(buttons);

    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_writeChecked, &QPushButton::clicked, this, &CompareDialog::writeChecked);
    connect(m_writeAll, &QPushButton::clicked, this, &CompareDialog::writeAll);
    connect(refreshButton, &QPushButton::clicked, this, &CompareDialog::refresh);
    resize(1000, 600);
    refresh();
}

void CompareDialog::refresh() {
    m_tree->clear();
    for (int i = 0; i < m_pages.size(); ++i) {
        const QList<SectionDifference> differences = m_pages[i]->differences();
        if (differences.isEmpty()) continue;
        auto* section = new QTreeWidgetItem(m_tree, {tr("%1 (%2)").arg(m_pages[i]->sectionTitle()).arg(differences.size())});
        section->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable | Qt::ItemIsAutoTristate);
        section->setCheckState(0, Qt::Checked);
        section->setFirstColumnSpanned(false);
        for (const SectionDifference& d : differences) {
            auto* item = new QTreeWidgetItem(section, {d.item, d.device, d.edited});
            item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable | Qt::ItemIsSelectable);
            item->setCheckState(0, Qt::Checked);
            item->setData(0, kKeyRole, d.key);
            item->setData(0, kPageRole, i);
            for (int column = 0; column < 3; ++column) item->setToolTip(column, item->text(column));
        }
        section->setExpanded(true);
    }
    const int count = differenceCount();
    if (count == 0) {
        new QTreeWidgetItem(m_tree, {tr("No differences: the device holds what you see.")});
    }
    m_writeChecked->setEnabled(count > 0);
    m_writeAll->setEnabled(count > 0);
}

int CompareDialog::differenceCount() const {
    int count = 0;
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) count += m_tree->topLevelItem(i)->childCount();
    return count;
}

void CompareDialog::checkOnly(const QStringList& keys) {
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem* section = m_tree->topLevelItem(i);
        for (int j = 0; j < section->childCount(); ++j) {
            QTreeWidgetItem* item = section->child(j);
            const bool on = keys.isEmpty() || keys.contains(item->data(0, kKeyRole).toString());
            item->setCheckState(0, on ? Qt::Checked : Qt::Unchecked);
        }
    }
}

void CompareDialog::writeChecked() { write(true); }

void CompareDialog::writeAll() { write(false); }

QString CompareDialog::reportText() const { return m_report->text(); }

void CompareDialog::write(bool onlyChecked) {
    QList<QPair<SectionPage*, QStringList>> queue;
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem* section = m_tree->topLevelItem(i);
        QStringList keys;
        int page = -1;
        for (int j = 0; j < section->childCount(); ++j) {
            QTreeWidgetItem* item = section->child(j);
            page = item->data(0, kPageRole).toInt();
            if (!onlyChecked || item->checkState(0) == Qt::Checked) keys << item->data(0, kKeyRole).toString();
        }
        if (!keys.isEmpty()) queue.append({m_pages.at(page), keys});
    }
    if (queue.isEmpty()) {
        m_report->setText(tr("Nothing selected: nothing was written."));
        return;
    }
    m_writeChecked->setEnabled(false);
    m_writeAll->setEnabled(false);
    m_report->setText(tr("Writing…"));
    writeNext(queue, {});
}

void CompareDialog::writeNext(QList<QPair<SectionPage*, QStringList>> queue, WriteReport report) {
    if (queue.isEmpty()) {
        m_report->setText(report.details());
        refresh();
        Q_EMIT writeFinished(report);
        return;
    }
    const auto [page, keys] = queue.takeFirst();
    QPointer<CompareDialog> self(this);
    page->writeItems(keys, [self, queue, report](const WriteReport& part) {
        WriteReport total = report;
        total.merge(part);
        if (self) self->writeNext(queue, total);
    });
}

}  // namespace cambench
