#include "analogue_cams_page.h"

#include "change_marker.h"
#include "device_session.h"
#include "workspace.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace cambench {

namespace {

QTableWidgetItem* numberItem(qint32 value) {
    auto* item = new QTableWidgetItem;
    item->setData(Qt::EditRole, value);
    return item;
}

}  // namespace

AnalogueCamsPage::AnalogueCamsPage(DeviceSession* session, Workspace* workspace, QWidget* parent)
    : SectionPage(parent),
      m_session(session),
      m_workspace(workspace),
      m_output(new QSpinBox),
      m_table(new QTableWidget(0, 2)),
      m_problems(new QLabel) {
    m_output->setRange(1, kAnalogueOutputs);
    m_table->setHorizontalHeaderLabels({tr("Position"), tr("Analogue value")});
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_problems->setWordWrap(true);
    auto* intro =
        new QLabel(tr("Between two base points the analogue output follows a straight "
                      "line (with interpolation on). Positions must rise from point to "
                      "point."));
    intro->setWordWrap(true);
    auto* read = new QPushButton(tr("Read from device"));
    auto* write = new QPushButton(tr("Write"));
    auto* add = new QPushButton(tr("Add point"));
    auto* remove = new QPushButton(tr("Remove point"));
    auto* top = new QHBoxLayout;
    top->addWidget(new QLabel(tr("Analogue output:")));
    top->addWidget(m_output);
    top->addWidget(read);
    top->addWidget(write);
    top->addStretch();
    top->addWidget(add);
    top->addWidget(remove);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(top);
    layout->addWidget(m_table);
    layout->addWidget(m_problems);
    connect(read, &QPushButton::clicked, this, [this] {
        if (mayReplaceEdits(this, tr("Analogue cams"), int(changes().size()))) readFromDevice();
    });
    connect(m_output, &QSpinBox::valueChanged, this, [this](int output) {
        // Another output replaces the table: unwritten points are not
        // dropped without asking.
        if (m_device.output != output && edited().points != m_device.points &&
            QMessageBox::question(
                this, tr("Analogue cams"),
                tr("The base points of analogue output %1 are edited and not written. "
                   "Discard them and show output %2?")
                    .arg(m_device.output)
                    .arg(output)) != QMessageBox::Yes) {
            const QSignalBlocker blocker(m_output);
            m_output->setValue(m_device.output);
            return;
        }
        readFromDevice();
    });
    connect(add, &QPushButton::clicked, this, [this] {
        const int row = m_table->rowCount();
        m_table->insertRow(row);
        m_table->setItem(row, 0, numberItem(m_workspace->info().minPosition));
        m_table->setItem(row, 1, numberItem(0));
        refreshEdits();
    });
    connect(remove, &QPushButton::clicked, this, [this] {
        if (m_table->currentRow() >= 0) m_table->removeRow(m_table->currentRow());
        refreshEdits();
    });
    connect(m_table, &QTableWidget::itemChanged, this, &AnalogueCamsPage::refreshEdits);
    m_problems->setText(tr("Not read from the device yet."));
    connect(write, &QPushButton::clicked, this, [this] {
        writeItems({}, [this](const PageWriteReport& report) {
            Q_EMIT statusMessage(tr("Analogue cams: %1").arg(report.summary()));
            if (!report.complete())
                QMessageBox::warning(this, tr("Analogue cams"), report.details());
        });
    });
}

void AnalogueCamsPage::readFromDevice() {
    const int output = m_output->value();
    m_session->run<AnalogueCamTrack>(
        this, tr("Read analogue cams"),
        [output](comm::CamConDevice& device, comm::JobContext&) {
            return device.readAnalogueCams(output);
        },
        [this](Result<AnalogueCamTrack> track) {
            if (!track) {
                Q_EMIT statusMessage(
                    tr("Reading analogue cams failed: %1").arg(track.error().message));
                return;
            }
            if (track->output != m_output->value()) return;  // another output chosen meanwhile
            m_device = track.value();
            setEdited(m_device);
            Q_EMIT statusMessage(tr("Analogue cams of output %1 read.").arg(m_device.output));
        });
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
    m_table->setRowCount(int(track.points.size()));
    for (int row = 0; row < track.points.size(); ++row) {
        m_table->setItem(row, 0, numberItem(track.points.at(row).position));
        m_table->setItem(row, 1, numberItem(track.points.at(row).value));
    }
    m_problems->clear();
    refreshEdits();
}

void AnalogueCamsPage::refreshEdits() {
    const QSignalBlocker blocker(m_table);
    const AnalogueCamTrack now = edited();
    const bool sameOutput = now.output == m_device.output;
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const bool onDevice = sameOutput && row < m_device.points.size();
        const AnaloguePoint device = onDevice ? m_device.points.at(row) : AnaloguePoint{};
        const QString none = tr("no such point");
        markEdited(m_table->item(row, 0),
                   !onDevice || now.points.at(row).position != device.position,
                   onDevice ? QString::number(device.position) : none);
        markEdited(m_table->item(row, 1), !onDevice || now.points.at(row).value != device.value,
                   onDevice ? QString::number(device.value) : none);
    }
    m_workspace->setPageEdits(sectionTitle(), int(changes().size()));
}

QList<PageChange> AnalogueCamsPage::changes() const {
    const AnalogueCamTrack now = edited();
    if (now == m_device || now.output != m_device.output) return {};
    return {{QStringLiteral("analogue:%1").arg(now.output),
             tr("Analogue output %1 base points").arg(now.output),
             tr("%n point(s)", nullptr, int(m_device.points.size())),
             tr("%n point(s)", nullptr, int(now.points.size()))}};
}

void AnalogueCamsPage::writeItems(const QStringList& keys,
                                  std::function<void(const PageWriteReport&)> done) {
    const QList<PageChange> all = changes();
    PageWriteReport report;
    if (all.isEmpty() || (!keys.isEmpty() && !keys.contains(all.first().key))) {
        report.addUnchanged();
        done(report);
        return;
    }
    const AnalogueCamTrack track = edited();
    const QStringList problems = validateAnalogueCamTrack(track, m_workspace->info());
    if (!problems.isEmpty()) {
        // Nothing goes to the device that it would refuse.
        m_problems->setText(problems.join(QLatin1Char('\n')));
        report.addRefusal(all.first().item, problems.join(QLatin1Char(' ')));
        done(report);
        return;
    }
    m_problems->clear();
    const QString label = all.first().item;
    m_session->run<Done>(
        this, tr("Write analogue cams"),
        [track](comm::CamConDevice& device, comm::JobContext&) {
            return device.writeAnalogueCams(track);
        },
        [this, track, label, done](Status written) {
            PageWriteReport result;
            if (written) {
                result.addWritten();
                m_device = track;
                refreshEdits();
            } else {
                result.addFailure(label, written.error());
            }
            done(result);
        });
}

}  // namespace cambench
