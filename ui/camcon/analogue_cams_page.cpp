#include "analogue_cams_page.h"
#include "ui/camcon/camcon_jobs.h"

#include "ui/change_marker.h"
#include "ui/device_session.h"
#include "ui/replace_edits_question.h"
#include "workspace.h"

#include "comm/camcon/usecases/value_text.h"

#include <QDateTime>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace cambench {

namespace {

QTableWidgetItem* numberItem(qint32 value) {
    auto* item = new QTableWidgetItem;
    item->setData(Qt::EditRole, value);
    return item;
}

}  // namespace

AnalogueCamsPage::AnalogueCamsPage(DeviceSession* session, Workspace* workspace, QWidget* parent)
    : CamConSectionPage(parent),
      m_session(session),
      m_workspace(workspace),
      m_output(new QSpinBox),
      m_table(new QTableWidget(0, 2)),
      m_state(new QLabel),
      m_problems(new QLabel) {
    m_output->setRange(1, kAnalogueOutputs);
    m_table->setHorizontalHeaderLabels({tr("Position"), tr("Analogue value")});
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_problems->setWordWrap(true);
    m_problems->setStyleSheet(QStringLiteral("QLabel { color: #b03a2e; }"));
    auto* intro =
        new QLabel(tr("Between two base points the analogue output follows a straight "
                      "line (with interpolation on). Positions must rise from point to "
                      "point."));
    intro->setWordWrap(true);
    auto* add = new QPushButton(tr("Add point"));
    auto* remove = new QPushButton(tr("Remove point"));
    ReadWriteBar bar(
        [this] {
            const bool edited =
                m_workspace->analogueCams().changedKeys().contains(m_output->value());
            if (mayReplaceEdits(this, tr("Analogue cams"), edited ? 1 : 0)) readFromDevice();
        },
        [this] { writeChanges(); });
    bar.before = {new QLabel(tr("Analogue output:")), m_output};
    bar.right = {add, remove};
    QHBoxLayout* top = readWriteBar(bar);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(top);
    layout->addWidget(m_state);
    layout->addWidget(m_table);
    layout->addWidget(m_problems);
    // Another output: the edits of this one stay in the workspace.
    connect(m_output, &QSpinBox::valueChanged, this, [this](int output) {
        if (!m_workspace->analogueCams().value(output) && m_session->isOnline())
            readFromDevice();
        else
            showOutput();
    });
    connect(add, &QPushButton::clicked, this, [this] {
        const int row = m_table->rowCount();
        m_table->insertRow(row);
        m_table->setItem(row, 0, numberItem(m_workspace->info().minPosition));
        m_table->setItem(row, 1, numberItem(0));
        takeTable();
    });
    connect(remove, &QPushButton::clicked, this, [this] {
        if (m_table->currentRow() >= 0) m_table->removeRow(m_table->currentRow());
        takeTable();
    });
    connect(m_table, &QTableWidget::itemChanged, this, &AnalogueCamsPage::takeTable);
    // A project opened, a write's outcome, another device: shown at once.
    connect(m_workspace, &Workspace::tableSectionsChanged, this, [this] {
        const std::optional<AnalogueCamTrack> track =
            m_workspace->analogueCams().value(m_output->value());
        if (!track || *track != edited())
            showOutput();
        else
            refreshMarks();
    });
    showOutput();
}

void AnalogueCamsPage::readFromDevice() {
    const int output = m_output->value();
    runOnCamCon<AnalogueCamTrack>(
        m_session, this, tr("Read analogue cams"),
        [output](comm::CamConDevice& device, comm::JobContext&) -> Result<AnalogueCamTrack> {
            // The device refuses the area of an output it does not have.
            const Result<int> count = device.readAnalogueOutputCount();
            if (!count) return count.error();
            if (output > *count) {
                return Error::usage(
                    *count == 0 ? tr("this device has no analogue outputs, so it has no "
                                     "analogue cams")
                                : tr("this device has analogue outputs 1..%1 only").arg(*count));
            }
            return device.readAnalogueCams(output);
        },
        [this](Result<AnalogueCamTrack> track) {
            if (!track) {
                Q_EMIT statusMessage(
                    tr("Reading analogue cams failed: %1").arg(track.error().message));
                return;
            }
            // The person chose to replace their edit of this output.
            m_workspace->analogueCams().merge({{track->output, *track}}, ValueSource::Device,
                                              false);
            m_workspace->setReadTime(ProjectPart::AnalogueCams, QDateTime::currentDateTimeUtc());
            Q_EMIT statusMessage(tr("Analogue cams of output %1 read.").arg(track->output));
        });
}

void AnalogueCamsPage::writeChanges(std::function<void(const WriteResult&)> done) {
    writeDifferences(m_session, m_workspace, std::move(done));
}

void AnalogueCamsPage::showOutput() {
    const std::optional<AnalogueCamTrack> track =
        m_workspace->analogueCams().value(m_output->value());
    {
        const QSignalBlocker blocker(m_table);
        const QList<AnaloguePoint> points = track ? track->points : QList<AnaloguePoint>();
        m_table->setRowCount(int(points.size()));
        for (int row = 0; row < points.size(); ++row) {
            m_table->setItem(row, 0, numberItem(points.at(row).position));
            m_table->setItem(row, 1, numberItem(points.at(row).value));
        }
    }
    refreshMarks();
}

AnalogueCamTrack AnalogueCamsPage::edited() const {
    AnalogueCamTrack track;
    track.output = m_output->value();
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const QTableWidgetItem* position = m_table->item(row, 0);
        const QTableWidgetItem* value = m_table->item(row, 1);
        track.points.append({position ? position->data(Qt::EditRole).toInt() : 0,
                             value ? value->data(Qt::EditRole).toInt() : 0});
    }
    return track;
}

void AnalogueCamsPage::setEdited(const AnalogueCamTrack& track) {
    if (track.output != m_output->value()) {
        const QSignalBlocker blocker(m_output);
        m_output->setValue(track.output);
    }
    m_workspace->analogueCams().edit(track.output, track);
    showOutput();
}

AnalogueCamTrack AnalogueCamsPage::onDevice() const {
    return m_workspace->analogueCams()
        .deviceValue(m_output->value())
        .value_or(AnalogueCamTrack{m_output->value(), {}});
}

void AnalogueCamsPage::takeTable() {
    const AnalogueCamTrack track = edited();
    m_workspace->analogueCams().edit(track.output, track);
    refreshMarks();
}

void AnalogueCamsPage::refreshMarks() {
    const QSignalBlocker blocker(m_table);
    const AnalogueCamTrack now = edited();
    const std::optional<AnalogueCamTrack> device =
        m_workspace->analogueCams().deviceValue(now.output);
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const bool onDevice = device && row < device->points.size();
        const AnaloguePoint point = onDevice ? device->points.at(row) : AnaloguePoint{};
        const QString none = device ? tr("no such point") : tr("not read");
        markEdited(m_table->item(row, 0),
                   !onDevice || now.points.at(row).position != point.position,
                   onDevice ? QString::number(point.position) : none);
        markEdited(m_table->item(row, 1), !onDevice || now.points.at(row).value != point.value,
                   onDevice ? QString::number(point.value) : none);
    }
    if (!device) {
        m_state->setText(tr("Analogue output %1: not read from the device.").arg(now.output));
    } else if (*device != now) {
        m_state->setText(tr("Analogue output %1: edited, not written. On the device: %2")
                             .arg(now.output)
                             .arg(usecases::analogueCamsText(*device)));
    } else {
        m_state->setText(tr("Analogue output %1: as on the device.").arg(now.output));
    }
    // Said where it is wrong before anything is sent.
    m_problems->setText(validateAnalogueCamTrack(now, m_workspace->info()).join(QLatin1Char('\n')));
}

QList<SectionDifference> AnalogueCamsPage::differences() const {
    QList<SectionDifference> list;
    for (int output : m_workspace->analogueCams().changedKeys()) {
        const std::optional<AnalogueCamTrack> device =
            m_workspace->analogueCams().deviceValue(output);
        list.append({WorkspaceItem::analogueCams(output), tr("Analogue output %1").arg(output),
                     device ? usecases::analogueCamsText(*device) : tr("not read"),
                     usecases::analogueCamsText(*m_workspace->analogueCams().value(output))});
    }
    return list;
}

}  // namespace cambench
