#include "compare_dialog.h"

#include "device_change_dialog.h"
#include "ui/camcon/camcon_jobs.h"
#include "ui/clock_time.h"

#include "incoming_values.h"
#include "ui/camcon/camcon_section_page.h"
#include "ui/device_session.h"
#include "workspace.h"

#include "comm/camcon/usecases/read_everything.h"

#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace cambench {

namespace {
constexpr int kItemRole = Qt::UserRole;

QString timeText(const QDateTime& utc) {
    return clockTime(utc.toLocalTime().time());
}
}  // namespace

CompareDialog::CompareDialog(DeviceSession* session, Workspace* workspace,
                             const QList<CamConSectionPage*>& pages, QWidget* parent)
    : QDialog(parent),
      m_session(session),
      m_workspace(workspace),
      m_pages(pages),
      m_source(new QLabel),
      m_progress(new QProgressBar),
      m_cancel(new QPushButton(tr("Cancel reading"))),
      m_tree(new QTreeWidget),
      m_report(new QPlainTextEdit) {
    setWindowTitle(tr("Compare with device"));
    m_source->setWordWrap(true);
    m_source->setObjectName(QStringLiteral("compareSource"));
    m_tree->setColumnCount(3);
    m_tree->setHeaderLabels({tr("Item"), tr("On the device"), tr("Edited on this PC")});
    m_tree->header()->setSectionResizeMode(QHeaderView::Interactive);
    m_tree->setColumnWidth(0, 280);
    m_tree->setColumnWidth(1, 360);
    m_tree->setWordWrap(true);
    m_report->setReadOnly(true);
    m_report->setMaximumHeight(fontMetrics().lineSpacing() * 8);
    m_report->hide();

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    m_writeChecked = buttons->addButton(tr("Write selected"), QDialogButtonBox::ActionRole);
    m_writeAll = buttons->addButton(tr("Write all"), QDialogButtonBox::ActionRole);
    m_refresh = buttons->addButton(tr("Read the device again"), QDialogButtonBox::ResetRole);

    auto* readRow = new QHBoxLayout;
    readRow->addWidget(m_progress, 1);
    readRow->addWidget(m_cancel);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_source);
    layout->addLayout(readRow);
    layout->addWidget(m_tree, 1);
    layout->addWidget(m_report);
    layout->addWidget(buttons);

    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_writeChecked, &QPushButton::clicked, this, &CompareDialog::writeChecked);
    connect(m_writeAll, &QPushButton::clicked, this, &CompareDialog::writeAll);
    connect(m_refresh, &QPushButton::clicked, this, &CompareDialog::refresh);
    connect(m_cancel, &QPushButton::clicked, this, &CompareDialog::cancelReading);
    connect(&m_session->worker(), &comm::JobRunner::jobProgress, this,
            [this](quint64 id, qint64 done, qint64 total, const QString& text) {
                if (id != m_readJob || total <= 0) return;
                m_progress->setRange(0, 1000);
                m_progress->setValue(int(done * 1000 / total));
                if (!text.isEmpty()) m_progress->setFormat(text + QStringLiteral(" (%p %)"));
            });
    resize(1000, 600);
    refresh();
}

void CompareDialog::setBusy(bool busy) {
    m_progress->setVisible(busy);
    m_cancel->setVisible(busy);
    m_refresh->setEnabled(!busy && m_session->isOnline());
    const bool any = !busy && differenceCount() > 0;
    m_writeChecked->setEnabled(any && m_session->isOnline());
    m_writeAll->setEnabled(any && m_session->isOnline());
}

void CompareDialog::refresh() {
    if (m_readJob != 0) return;
    if (!m_session->isOnline()) {
        const QDateTime read = m_workspace->lastReadTime();
        m_source->setText(
            read.isValid() ? tr("Not connected: compared with the device values read at %1. The "
                                "device may have changed since.")
                                 .arg(timeText(read))
                           : tr("Not connected, and nothing was read from a device: every edited "
                                "item is listed as \"not read\"."));
        showDifferences();
        setBusy(false);
        Q_EMIT compared();
        return;
    }
    m_source->setText(tr("Reading what the device holds now…"));
    m_progress->setRange(0, 0);
    m_progress->setFormat(QStringLiteral("%p %"));
    m_tree->clear();
    setBusy(true);
    QPointer<CompareDialog> self(this);
    Workspace* workspace = m_workspace;
    m_readJob = runOnCamCon<usecases::ReadEverything>(
        m_session, this, tr("Compare with device"),
        [](comm::CamConDevice& device, comm::JobContext& job) -> Result<usecases::ReadEverything> {
            const Result<DeviceInfo> identity = device.readInfo();
            if (!identity) return identity.error();
            return usecases::readEverything(device, identity.value(),
                                            usecases::UseCaseProgress::of(job));
        },
        [this, workspace](Result<usecases::ReadEverything> result) {
            m_readJob = 0;
            if (!result) {
                const QDateTime read = workspace->lastReadTime();
                m_source->setText(
                    (result.error().kind == ErrorKind::Cancelled
                         ? tr("Reading cancelled.")
                         : tr("The device could not be read: %1").arg(result.error().message)) +
                    QLatin1Char(' ') +
                    (read.isValid() ? tr("Shown: the device values read at %1.").arg(timeText(read))
                                    : tr("Nothing was read from the device: edited items are "
                                         "listed as \"not read\".")));
            } else {
                // Compare never replaces an edit: edited items keep theirs,
                // the rest follows the device.
                m_deviceChanges = deviceChanges(*workspace, result->project);
                mergeIncoming(*workspace, result->project, ValueSource::Device,
                              {EditSection::Cams, EditSection::OutputSettings,
                               EditSection::Settings, EditSection::Users, EditSection::Plc});
                QString text =
                    tr("Device values read at %1.").arg(timeText(QDateTime::currentDateTimeUtc()));
                if (!result->skipped.isEmpty())
                    text += QLatin1Char(' ') +
                            tr("Not read: %1").arg(result->skipped.join(QLatin1Char(' ')));
                m_source->setText(text);
            }
            showDifferences();
            setBusy(false);
            Q_EMIT compared();
        });
}

void CompareDialog::cancelReading() {
    if (m_readJob != 0) m_session->worker().cancel(m_readJob);
}

QList<WorkspaceItem> CompareDialog::uncheckedItems() const {
    QList<WorkspaceItem> items;
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem* section = m_tree->topLevelItem(i);
        for (int j = 0; j < section->childCount(); ++j) {
            const QVariant data = section->child(j)->data(0, kItemRole);
            if (data.isValid() && section->child(j)->checkState(0) != Qt::Checked)
                items << data.value<WorkspaceItem>();
        }
    }
    return items;
}

QString CompareDialog::copyNote() const {
    const std::optional<Workspace::CarriedFrom>& carried = m_workspace->carriedFrom();
    if (!carried || carried->carry != CarryOver::Everything) return {};
    return tr("The edits hold a copy of the values of %1, made when this device came on the line.")
        .arg(deviceName(carried->device));
}

void CompareDialog::showDifferences() {
    // What the person left unticked stays so (a write of the ticked ones
    // leaves the others different and unticked).
    const QList<WorkspaceItem> unchecked = uncheckedItems();
    m_tree->clear();
    const QString copy = copyNote();
    m_tree->setHeaderLabels({tr("Item"), tr("On the device"),
                             copy.isEmpty() ? tr("Edited on this PC") : tr("Copy to write")});
    if (!copy.isEmpty() && !m_source->text().contains(copy))
        m_source->setText(m_source->text() + QLatin1Char(' ') + copy);
    if (!m_deviceChanges.isEmpty()) {
        auto* section = new QTreeWidgetItem(
            m_tree,
            {tr("Changed on the device since it was last read (%1)").arg(m_deviceChanges.size())});
        for (const QString& line : m_deviceChanges) {
            auto* item = new QTreeWidgetItem(section, {line});
            item->setFirstColumnSpanned(true);
        }
        section->setExpanded(true);
    }
    int count = 0;
    for (CamConSectionPage* page : m_pages) {
        const QList<SectionDifference> differences = page->differences();
        if (differences.isEmpty()) continue;
        count += int(differences.size());
        auto* section = new QTreeWidgetItem(
            m_tree, {tr("%1 (%2)").arg(page->sectionTitle()).arg(differences.size())});
        section->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable | Qt::ItemIsAutoTristate);
        section->setCheckState(0, Qt::Checked);
        for (const SectionDifference& d : differences) {
            auto* item = new QTreeWidgetItem(section, {d.label, d.device, d.edited});
            item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable | Qt::ItemIsSelectable);
            item->setCheckState(0, unchecked.contains(d.item) ? Qt::Unchecked : Qt::Checked);
            item->setData(0, kItemRole, QVariant::fromValue(d.item));
            for (int column = 0; column < 3; ++column) item->setToolTip(column, item->text(column));
        }
        section->setExpanded(true);
    }
    if (count == 0) {
        auto* none =
            new QTreeWidgetItem(m_tree, {tr("No differences: the device holds what you see.")});
        none->setFirstColumnSpanned(true);
    }
}

int CompareDialog::differenceCount() const {
    int count = 0;
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem* section = m_tree->topLevelItem(i);
        for (int j = 0; j < section->childCount(); ++j)
            count += section->child(j)->data(0, kItemRole).isValid() ? 1 : 0;
    }
    return count;
}

void CompareDialog::checkOnly(const QList<WorkspaceItem>& items) {
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem* section = m_tree->topLevelItem(i);
        for (int j = 0; j < section->childCount(); ++j) {
            QTreeWidgetItem* item = section->child(j);
            const QVariant data = item->data(0, kItemRole);
            if (!data.isValid()) continue;
            const bool on = items.isEmpty() || items.contains(data.value<WorkspaceItem>());
            item->setCheckState(0, on ? Qt::Checked : Qt::Unchecked);
        }
    }
}

void CompareDialog::writeChecked() {
    write(true);
}

void CompareDialog::writeAll() {
    write(false);
}

QString CompareDialog::reportText() const {
    return m_report->toPlainText();
}

QString CompareDialog::sourceText() const {
    return m_source->text();
}

void CompareDialog::write(bool onlyChecked) {
    QList<WorkspaceItem> items;
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem* section = m_tree->topLevelItem(i);
        for (int j = 0; j < section->childCount(); ++j) {
            QTreeWidgetItem* item = section->child(j);
            const QVariant data = item->data(0, kItemRole);
            if (data.isValid() && (!onlyChecked || item->checkState(0) == Qt::Checked))
                items << data.value<WorkspaceItem>();
        }
    }
    m_report->show();
    if (items.isEmpty()) {
        m_report->setPlainText(tr("Nothing selected: nothing was written."));
        return;
    }
    m_writeChecked->setEnabled(false);
    m_writeAll->setEnabled(false);
    m_report->setPlainText(tr("Writing…"));
    writeToDevice(this, m_session, m_workspace, items, [this](const WriteResult& result) {
        const QString details = writeDetails(result);
        const QString copy = copyNote();
        m_report->setPlainText((copy.isEmpty() ? QString() : copy + QLatin1Char('\n')) +
                               writeSummary(result) +
                               (details.isEmpty() ? QString() : QLatin1Char('\n') + details));
        m_deviceChanges.clear();
        showDifferences();
        setBusy(false);
        Q_EMIT writeFinished(result);
    });
}

}  // namespace cambench
