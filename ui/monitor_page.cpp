#include "monitor_page.h"

#include "device_session.h"
#include "led_strip.h"
#include "trend_chart.h"
#include "workspace.h"

#include <QCheckBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace cambench {

namespace {
const QString kPollKey = QStringLiteral("monitor");

QLabel* bigValue() {
    auto* label = new QLabel(QStringLiteral("—"));
    QFont font = label->font();
    font.setPointSizeF(font.pointSizeF() * 1.6);
    font.setBold(true);
    label->setFont(font);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}
}  // namespace

MonitorPage::MonitorPage(DeviceSession* session, Workspace* workspace, QWidget* parent)
    : SectionPage(parent),
      m_session(session),
      m_workspace(workspace),
      m_position(bigValue()),
      m_speed(bigValue()),
      m_program(bigValue()),
      m_newProgram(new QSpinBox),
      m_error(new QLabel),
      m_reset(new QPushButton(tr("Reset error"))),
      m_outputs(new LedStrip),
      m_inputs(new LedStrip),
      m_trend(new TrendChart),
      m_pause(new QCheckBox(tr("Pause trend"))),
      m_rate(new QSpinBox) {
    auto* values = new QGroupBox(tr("Axis"));
    auto* form = new QFormLayout(values);
    form->addRow(tr("Position:"), m_position);
    form->addRow(tr("Speed:"), m_speed);
    form->addRow(tr("Active program:"), m_program);
    auto* select = new QPushButton(tr("Activate"));
    select->setToolTip(tr("Make this program the active one on the device."));
    auto* programRow = new QHBoxLayout;
    programRow->addWidget(m_newProgram);
    programRow->addWidget(select);
    programRow->addStretch();
    form->addRow(tr("Switch to program:"), programRow);
    auto* errorRow = new QHBoxLayout;
    errorRow->addWidget(m_error, 1);
    errorRow->addWidget(m_reset);
    form->addRow(tr("State:"), errorRow);
    m_error->setWordWrap(true);

    auto* leds = new QGroupBox(tr("Outputs and inputs"));
    auto* ledLayout = new QVBoxLayout(leds);
    ledLayout->addWidget(new QLabel(tr("Outputs")));
    ledLayout->addWidget(m_outputs);
    ledLayout->addWidget(new QLabel(tr("Inputs")));
    ledLayout->addWidget(m_inputs);
    ledLayout->addStretch();

    auto* top = new QHBoxLayout;
    top->addWidget(values, 2);
    top->addWidget(leds, 3);

    m_rate->setRange(100, 5000);
    m_rate->setSingleStep(100);
    m_rate->setValue(250);
    m_rate->setSuffix(tr(" ms"));
    m_rate->setToolTip(tr("How often the device is asked for its state."));
    auto* trendControls = new QHBoxLayout;
    trendControls->addWidget(new QLabel(tr("Poll every")));
    trendControls->addWidget(m_rate);
    trendControls->addWidget(m_pause);
    trendControls->addStretch();

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addLayout(trendControls);
    layout->addWidget(m_trend, 1);

    m_timer.setInterval(m_rate->value());
    m_clock.start();
    connect(&m_timer, &QTimer::timeout, this, &MonitorPage::poll);
    connect(m_rate, &QSpinBox::valueChanged, this, &MonitorPage::setPollInterval);
    connect(m_session, &DeviceSession::stateChanged, this, &MonitorPage::updateRunning);
    connect(select, &QPushButton::clicked, this, [this] {
        const int program = m_newProgram->value();
        m_session->run<Done>(
            this, tr("Select program"),
            [program](comm::CamConDevice& client, comm::JobContext&) { return client.selectProgram(program); },
            [this, program](Status status) {
                Q_EMIT statusMessage(status ? tr("Program %1 is active.").arg(program)
                                            : tr("Program %1 not activated: %2")
                                                  .arg(program)
                                                  .arg(status.error().message));
            });
    });
    connect(m_reset, &QPushButton::clicked, this, [this] {
        m_session->run<Done>(
            this, tr("Reset error"),
            [](comm::CamConDevice& client, comm::JobContext&) { return client.resetError(); },
            [this](Status status) {
                Q_EMIT statusMessage(status ? tr("Error reset sent.")
                                            : tr("Error not reset: %1").arg(status.error().message));
            });
    });
    const auto resize = [this] {
        m_newProgram->setRange(0, std::max(0, m_workspace->info().programs - 1));
        m_outputs->setCount(m_workspace->info().outputs);
        m_inputs->setCount(m_workspace->info().inputs);
    };
    connect(m_workspace, &Workspace::infoChanged, this, resize);
    resize();
    showStatus({});
    updateRunning();
}

void MonitorPage::setPollInterval(int ms) {
    m_rate->setValue(ms);
    m_timer.setInterval(ms);
}

void MonitorPage::setPaused(bool paused) { m_pause->setChecked(paused); }

int MonitorPage::trendSamples() const { return m_trend->sampleCount(); }

void MonitorPage::updateRunning() {
    if (m_session->isOnline()) {
        if (!m_timer.isActive()) m_timer.start();
    } else {
        m_timer.stop();
        m_pollPending = false;
        Q_EMIT pollingStopped();
    }
}

void MonitorPage::poll() {
    // One poll in flight at a time; the key also collapses queued ones. A
    // poll whose answer never came (cancelled with the queue) expires.
    if (m_pollPending && m_pollSince.elapsed() < 10000) return;
    m_pollPending = true;
    m_pollSince.start();
    const int outputs = m_workspace->info().outputs;
    const int inputs = m_workspace->info().inputs;
    m_session->run<DeviceStatus>(
        this, tr("Monitor"),
        [outputs, inputs](comm::CamConDevice& client, comm::JobContext&) {
            return client.readStatus(outputs, inputs);
        },
        [this](Result<DeviceStatus> status) {
            m_pollPending = false;
            if (status) showStatus(status.value());
        },
        comm::JobPriority::Poll, kPollKey);
}

QString MonitorPage::errorText(int errorState) {
    switch (errorState) {
        case 0:
            return tr("OK");
        case 1:
        case 2:
        case 3:
            return tr("Actual-value error %1: check the encoder and its cable, then reset.")
                .arg(errorState);
        case 4:
            return tr("Output error: an output is overloaded or short-circuited; fix it, then reset.");
        case 0xFF:
            return tr("EEPROM checksum error: the stored data are damaged; restore a backup.");
        default:
            return tr("Unknown error state %1").arg(errorState);
    }
}

void MonitorPage::showStatus(const DeviceStatus& status) {
    const bool known = m_session->isOnline();
    m_position->setText(known ? (status.positionText.trimmed().isEmpty()
                                     ? QString::number(status.position)
                                     : status.positionText.trimmed())
                              : QStringLiteral("—"));
    m_speed->setText(known ? (status.speedText.trimmed().isEmpty() ? QString::number(status.speed)
                                                                   : status.speedText.trimmed())
                           : QStringLiteral("—"));
    m_program->setText(known ? QString::number(status.activeProgram) : QStringLiteral("—"));
    m_error->setText(known ? errorText(status.errorState) : tr("offline"));
    m_reset->setEnabled(known && status.errorState != 0);
    if (!status.outputs.isEmpty()) m_outputs->setStates(status.outputs);
    if (!status.inputs.isEmpty()) m_inputs->setStates(status.inputs);
    if (!known) return;
    if (!m_pause->isChecked())
        m_trend->addSample(m_clock.elapsed() / 1000.0, status.position, status.speed);
    Q_EMIT statusUpdated(status);
}

}  // namespace cambench
