#include "dead_time_modes_page.h"
#include "ui/camcon/camcon_jobs.h"

#include "milliseconds_text.h"
#include "ui/change_marker.h"
#include "ui/device_session.h"
#include "ui/replace_edits_question.h"
#include "workspace.h"

#include "comm/camcon/usecases/value_text.h"

#include "ui/camcon/cameditor/cam_document.h"

#include <QComboBox>
#include <QDateTime>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

namespace cambench {

namespace {

// Dead times are kept in 0.1 ms steps and shown in ms.
constexpr double kTenthsPerMs = 10.0;

QTableWidgetItem* msItem(qint32 tenths) {
    auto* item = new QTableWidgetItem;
    item->setData(Qt::EditRole, tenths / kTenthsPerMs);
    return item;
}

qint32 tenthsOf(const QTableWidgetItem* item) {
    return item ? qint32(qRound(item->data(Qt::EditRole).toDouble() * kTenthsPerMs)) : 0;
}

}  // namespace

DeadTimeModesPage::DeadTimeModesPage(DeviceSession* session, Workspace* workspace, QWidget* parent)
    : CamConSectionPage(parent),
      m_session(session),
      m_workspace(workspace),
      m_table(new QTableWidget(0, COUNT)),
      m_note(new QLabel) {
    m_table->setHorizontalHeaderLabels({tr("Output"), tr("Mode"), tr("Dead time (ms)"),
                                        tr("Switch-on (ms)"), tr("Switch-off / time (ms)")});
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    auto* intro = new QLabel(
        tr("Normal: one dead time moves both switching points. On/off: the switch-on and the "
           "switch-off point each have their own. Path-time: the output switches on early by "
           "the switch-on dead time and stays on for the switching time."));
    intro->setWordWrap(true);
    ReadWriteBar bar(
        [this] {
            if (mayReplaceEdits(this, tr("Dead-time modes"), int(differences().size())))
                readFromDevice();
        },
        [this] { writeChanges(); });
    bar.right = {m_note};
    QHBoxLayout* buttons = readWriteBar(bar);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(buttons);
    layout->addWidget(m_table);
    connect(m_table, &QTableWidget::itemChanged, this,
            [this](QTableWidgetItem* item) { takeRow(item->row()); });
    connect(m_workspace, &Workspace::deadTimeModesChanged, this, &DeadTimeModesPage::showModes);
    // Another device answered: the note says the rows are not this one's.
    connect(m_workspace, &Workspace::otherDeviceNoteChanged, this, &DeadTimeModesPage::showModes);
    showModes();
}

void DeadTimeModesPage::readFromDevice() {
    const int outputs = m_workspace->info().deadTimeOutputs;
    Q_EMIT statusMessage(tr("Reading dead-time modes…"));
    runOnCamCon<DeadTimeModes>(
        m_session, this, tr("Read dead-time modes"),
        [outputs](comm::CamConDevice& device, comm::JobContext&) {
            return device.readDeadTimeModes(outputs);
        },
        [this](Result<DeadTimeModes> modes) {
            if (!modes) {
                Q_EMIT statusMessage(
                    tr("Reading dead-time modes failed: %1").arg(modes.error().message));
                return;
            }
            // The person chose to replace their edits (if any); what waits
            // for the first read (a project's, or carried from another
            // device) stays.
            auto& copies = m_workspace->deadTimeModes();
            m_workspace->mergeDeadTimeModes(modes.value(), ValueSource::Device, !copies.known());
            m_workspace->setReadTime(ProjectPart::DeadTimeModes, QDateTime::currentDateTimeUtc());
            Q_EMIT statusMessage(tr("Dead-time modes read."));
        });
}

void DeadTimeModesPage::showModes() {
    const DeadTimeModes device = onDevice();
    {
        // Filled row by row: the edits are marked once all rows are there.
        const QSignalBlocker blocker(m_table);
        if (shownOutputs() != device.keys()) {
            m_table->setRowCount(0);
            m_table->setRowCount(int(device.size()));
            int row = 0;
            for (auto it = device.begin(); it != device.end(); ++it, ++row) {
                auto* output = new QTableWidgetItem(QString::number(it.key()));
                output->setFlags(Qt::ItemIsEnabled);
                output->setData(Qt::UserRole, it.key());
                m_table->setItem(row, OutputColumn, output);
                auto* mode = new QComboBox;
                mode->addItem(tr("Normal"), int(DeadTimeMode::Normal));
                mode->addItem(tr("On/off"), int(DeadTimeMode::SeparateOnOff));
                mode->addItem(tr("Path-time"), int(DeadTimeMode::PathTime));
                connect(mode, &QComboBox::currentIndexChanged, this,
                        [this, output] { takeRow(output->row()); });
                m_table->setCellWidget(row, ModeColumn, mode);
                m_table->setItem(row, NormalColumn, msItem(0));
                m_table->setItem(row, OnColumn, msItem(0));
                m_table->setItem(row, OffColumn, msItem(0));
            }
        }
        for (auto it = device.begin(); it != device.end(); ++it)
            fillRow(rowOf(it.key()), edited(it.key()));
    }
    if (!device.isEmpty())
        m_note->setText(
            tr("Largest dead time: %1").arg(millisecondsText(m_workspace->info().maxDeadTime)));
    else if (m_workspace->otherDeviceNote().isEmpty())
        m_note->setText(tr("Not read from the device yet."));
    else
        m_note->setText(tr("Not read from this device yet."));
    markEdits();
}

void DeadTimeModesPage::markEdits() {
    // Setting a font changes the item: no recursion through itemChanged.
    const QSignalBlocker blocker(m_table);
    for (int row = 0; row < m_table->rowCount(); ++row) {
        QTableWidgetItem* outputItem = m_table->item(row, OutputColumn);
        if (!outputItem) continue;
        const int output = outputItem->data(Qt::UserRole).toInt();
        const OutputDeadTime device =
            m_workspace->deviceDeadTimeMode(output).value_or(OutputDeadTime{});
        const OutputDeadTime now = edited(output);
        auto* mode = qobject_cast<QComboBox*>(m_table->cellWidget(row, ModeColumn));
        if (!mode) continue;  // the row is being filled
        QFont modeFont = mode->font();
        modeFont.setBold(now.mode != device.mode);
        mode->setFont(modeFont);
        mode->setToolTip(
            now.mode != device.mode
                ? tr("On the device: %1").arg(mode->itemText(mode->findData(int(device.mode))))
                : QString());
        bool any = now.mode != device.mode;
        any |= markEdited(m_table->item(row, NormalColumn), now.normal != device.normal,
                          millisecondsText(device.normal));
        any |= markEdited(m_table->item(row, OnColumn), now.on != device.on,
                          millisecondsText(device.on));
        any |= markEdited(m_table->item(row, OffColumn), now.off != device.off,
                          millisecondsText(device.off));
        outputItem->setText((any ? changedMarker() : QString()) + QString::number(output));
        markEdited(outputItem, any, QString());
        outputItem->setToolTip(any ? tr("Edited, not written to the device") : QString());
    }
}

void DeadTimeModesPage::takeRow(int row) {
    const QTableWidgetItem* outputItem = m_table->item(row, OutputColumn);
    const auto* mode = qobject_cast<const QComboBox*>(m_table->cellWidget(row, ModeColumn));
    if (!outputItem || !mode) return;  // the row is being filled
    m_workspace->editDeadTimeMode(outputItem->data(Qt::UserRole).toInt(),
                                  OutputDeadTime{DeadTimeMode(mode->currentData().toInt()),
                                                 tenthsOf(m_table->item(row, NormalColumn)),
                                                 tenthsOf(m_table->item(row, OnColumn)),
                                                 tenthsOf(m_table->item(row, OffColumn))});
}

void DeadTimeModesPage::fillRow(int row, const OutputDeadTime& deadTime) {
    auto* mode = qobject_cast<QComboBox*>(m_table->cellWidget(row, ModeColumn));
    if (!mode) return;
    {
        const QSignalBlocker blocker(mode);
        mode->setCurrentIndex(mode->findData(int(deadTime.mode)));
    }
    m_table->item(row, NormalColumn)->setData(Qt::EditRole, deadTime.normal / kTenthsPerMs);
    m_table->item(row, OnColumn)->setData(Qt::EditRole, deadTime.on / kTenthsPerMs);
    m_table->item(row, OffColumn)->setData(Qt::EditRole, deadTime.off / kTenthsPerMs);
}

OutputDeadTime DeadTimeModesPage::edited(int output) const {
    return m_workspace->deadTimeMode(output).value_or(OutputDeadTime{});
}

void DeadTimeModesPage::setEdited(int output, const OutputDeadTime& deadTime) {
    if (onDevice().contains(output)) m_workspace->editDeadTimeMode(output, deadTime);
}

DeadTimeModes DeadTimeModesPage::onDevice() const {
    return m_workspace->deviceDeadTimeModes();
}

QList<int> DeadTimeModesPage::shownOutputs() const {
    QList<int> outputs;
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const QTableWidgetItem* item = m_table->item(row, OutputColumn);
        outputs << (item ? item->data(Qt::UserRole).toInt() : 0);
    }
    return outputs;
}

int DeadTimeModesPage::rowOf(int output) const {
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const QTableWidgetItem* item = m_table->item(row, OutputColumn);
        if (item && item->data(Qt::UserRole).toInt() == output) return row;
    }
    return -1;
}

QList<SectionDifference> DeadTimeModesPage::differences() const {
    QList<SectionDifference> list;
    const DeadTimeModes device = onDevice();
    for (auto it = device.begin(); it != device.end(); ++it) {
        // A mode, or only its dead time (word 0, which the Dead times page
        // shows too): the mode's write carries every word of it.
        if (!m_workspace->deadTimeModeChanged(it.key())) continue;
        const OutputDeadTime now = edited(it.key());
        list.append({WorkspaceItem::deadTimeMode(it.key()),
                     tr("Output %1 dead-time mode").arg(it.key()),
                     usecases::deadTimeModeText(it.value()), usecases::deadTimeModeText(now)});
    }
    return list;
}

void DeadTimeModesPage::writeChanges(std::function<void(const WriteResult&)> done) {
    // Checked against the connected device before the first byte, written
    // and read back item by item; the device copy follows the report
    // (Workspace::setDeviceDeadTimeMode).
    writeDifferences(m_session, m_workspace, std::move(done));
}

}  // namespace cambench
