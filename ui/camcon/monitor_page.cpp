#include "monitor_page.h"

#include "ui/camcon/camcon_jobs.h"
#include "ui/family_gui.h"

#include "model/camcon/camcon_family_id.h"
#include "ui/device_session.h"
#include "ui/led_strip.h"
#include "ui/live_freshness.h"
#include "ui/trend_chart.h"
#include "workspace.h"

#include <QCheckBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>

namespace cambench {

namespace {
const QString kPollKey = QStringLiteral("monitor");
constexpr int kDefaultIntervalMs = 250;
constexpr int kIntervalStepMs = 50;
// Head room over the measured line time, so that a normal answer always
// arrives before the next cycle and only a missing one counts as missed.
constexpr double kLineMargin = 1.5;
// Behind pages without live values the poll goes on this slowly: the link's
// health (the banner, the indicator) must not depend on the page shown.
constexpr int kHeartbeatMs = 2000;

QLabel* bigValue() {
    auto* label = new QLabel(QStringLiteral("—"));
    QFont font = label->font();
    font.setPointSizeF(font.pointSizeF() * 1.6);
    font.setBold(true);
    label->setFont(font);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

// The readouts show the device's formatted texts (?IFGWG, ?SPEED); the
// trend plots the same numbers, the raw value only when the text is none.
double plotted(const QString& text, qint32 raw) {
    bool ok = false;
    const double value = text.trimmed().toDouble(&ok);
    return ok ? value : double(raw);
}

QString readout(const QString& text, qint32 raw) {
    const QString trimmed = text.trimmed();
    if (trimmed.isEmpty()) return QLocale().toString(raw);
    // The device formats with a decimal point; shown in the user's language
    // ("6,0" in German) with as many decimals as the device gave.
    bool number = false;
    const double value = trimmed.toDouble(&number);
    if (!number) return trimmed;
    const int point = int(trimmed.indexOf(QLatin1Char('.')));
    const int decimals = point < 0 ? 0 : int(trimmed.size()) - point - 1;
    return QLocale().toString(value, 'f', decimals);
}
}  // namespace

MonitorPage::MonitorPage(DeviceSession* session, Workspace* workspace, QWidget* parent)
    : CamConSectionPage(parent),
      m_session(session),
      m_workspace(workspace),
      m_freshness(new QLabel),
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
      m_rate(new QSpinBox),
      m_rateNote(new QLabel) {
    m_freshness->setObjectName(QStringLiteral("monitorFreshness"));
    m_freshness->setWordWrap(true);
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
    m_rate->setSingleStep(kIntervalStepMs);
    m_rate->setValue(kDefaultIntervalMs);
    m_rate->setSuffix(tr(" ms"));
    m_rate->setToolTip(
        tr("How often the device is asked for its state. CamBench polls no faster "
           "than the line can answer."));
    m_rateNote->setWordWrap(true);
    m_rateNote->setObjectName(QStringLiteral("pollRateNote"));
    auto* trendControls = new QHBoxLayout;
    trendControls->addWidget(new QLabel(tr("Poll every")));
    trendControls->addWidget(m_rate);
    trendControls->addWidget(m_pause);
    trendControls->addWidget(m_rateNote, 1);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_freshness);
    layout->addLayout(top);
    layout->addLayout(trendControls);
    layout->addWidget(m_trend, 1);

    m_timer.setInterval(kDefaultIntervalMs);
    connect(&m_timer, &QTimer::timeout, this, &MonitorPage::pollCycle);
    connect(m_rate, &QSpinBox::valueChanged, this, [this](int ms) {
        if (ms == m_liveInterval) return;  // our own adjustment
        m_requestedInterval = ms;
        setLiveInterval(ms);
        m_rateNote->clear();
    });
    connect(m_session, &DeviceSession::stateChanged, this, &MonitorPage::updateRunning);
    connect(m_session->freshness(), &LiveFreshness::changed, this, &MonitorPage::showFreshness);
    comm::JobRunner* worker = &m_session->worker();
    connect(worker, &comm::JobRunner::jobStarted, this, [this](quint64 id) {
        if (id == m_pollJob) m_lineClock.start();
    });
    connect(worker, &comm::JobRunner::jobFinished, this, [this](quint64 id) {
        // Removed from the queue (cancel, reconnect) without an answer.
        if (id == m_pollJob) m_pollJob = 0;
    });
    connect(select, &QPushButton::clicked, this, [this] {
        const int program = m_newProgram->value();
        runOnCamCon<Done>(
            m_session, this, tr("Select program"),
            [program](comm::CamConDevice& client, comm::JobContext&) {
                return client.selectProgram(program);
            },
            [this, program](Status status) {
                Q_EMIT statusMessage(status ? tr("Program %1 is active.").arg(program)
                                            : tr("Program %1 not activated: %2")
                                                  .arg(program)
                                                  .arg(status.error().message));
            });
    });
    connect(m_reset, &QPushButton::clicked, this, [this] {
        runOnCamCon<Done>(
            m_session, this, tr("Reset error"),
            [](comm::CamConDevice& client, comm::JobContext&) { return client.resetError(); },
            [this](Status status) {
                Q_EMIT statusMessage(status
                                         ? tr("Error reset sent.")
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
    m_reset->setEnabled(false);
    showFreshness();
    updateRunning();
}

void MonitorPage::forgetDevice() {
    m_trend->clear();
    m_clock.invalidate();
}

void MonitorPage::setPollInterval(int ms) {
    m_requestedInterval = ms;
    setLiveInterval(ms);
    m_rateNote->clear();
}

void MonitorPage::setLiveInterval(int ms) {
    m_liveInterval = ms;
    m_rate->setValue(ms);
    m_timer.setInterval(m_liveWanted ? ms : std::max(ms, kHeartbeatMs));
}

QString MonitorPage::rateNote() const {
    return m_rateNote->text();
}

int MonitorPage::trendSamples() const {
    return m_trend->sampleCount();
}

void MonitorPage::setTimerDriven(bool on) {
    m_timerDriven = on;
    updateRunning();
}

void MonitorPage::setLiveWanted(bool wanted) {
    if (m_liveWanted == wanted) return;
    m_liveWanted = wanted;
    updateRunning();
}

bool MonitorPage::onCamCon() const {
    // Connected to another family, the CamCon's polls would only fail
    // there and call that line silent.
    return m_session->isOnline() && sessionFamily(*m_session) == camconFamilyId;
}

void MonitorPage::updateRunning() {
    if (!onCamCon()) {
        m_timer.stop();
        Q_EMIT liveEnded();
        return;
    }
    // Live pages poll at the chosen rate; every other page keeps a slow
    // heartbeat, so that a silent line turns stale wherever the user is.
    setLiveInterval(m_liveInterval);
    if (m_timerDriven && !m_timer.isActive()) {
        m_timer.start();
        pollCycle();  // the first values now, not one interval later
    }
    if (!m_timerDriven) m_timer.stop();
    if (!m_liveWanted) Q_EMIT liveEnded();
}

void MonitorPage::pollCycle() {
    if (!onCamCon()) return;
    if (m_pollJob != 0) {
        // Still waiting in the queue behind a user job: the line is busy,
        // not silent. On the line for a whole cycle: no answer.
        if (m_lineClock.isValid()) m_session->freshness()->missed();
        return;
    }
    const int outputs = m_workspace->info().outputs;
    const int inputs = m_workspace->info().inputs;
    m_lineClock.invalidate();
    m_pollJob = runOnCamCon<DeviceStatus>(
        m_session, this, tr("Monitor"),
        [outputs, inputs](comm::CamConDevice& client, comm::JobContext&) {
            return client.readStatus(outputs, inputs);
        },
        [this](Result<DeviceStatus> status) { onPollDone(status); }, comm::JobPriority::Poll,
        kPollKey);
}

void MonitorPage::onPollDone(const Result<DeviceStatus>& status) {
    const qint64 lineMs = m_lineClock.isValid() ? m_lineClock.elapsed() : 0;
    m_pollJob = 0;
    m_lineClock.invalidate();
    if (!status) {
        if (status.error().kind != ErrorKind::Cancelled) m_session->freshness()->missed();
        return;
    }
    adaptInterval(lineMs);
    m_session->freshness()->answered(QDateTime::currentDateTime());
    showStatus(status.value());
}

void MonitorPage::adaptInterval(qint64 lineMs) {
    if (!m_timerDriven) return;
    if (lineMs * kLineMargin <= m_requestedInterval) {
        // The line carries the chosen rate again (after a stall): back to it.
        if (m_liveInterval != m_requestedInterval) {
            setLiveInterval(m_requestedInterval);
            m_rateNote->clear();
        }
        return;
    }
    if (lineMs * kLineMargin <= m_liveInterval) return;
    const int needed = int(std::ceil(lineMs * kLineMargin / kIntervalStepMs)) * kIntervalStepMs;
    setLiveInterval(needed);
    m_rateNote->setText(
        tr("The line needs about %1 ms per poll: polling every %2 ms instead of %3 ms.")
            .arg(lineMs)
            .arg(needed)
            .arg(m_requestedInterval));
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
            return tr(
                "Output error: an output is overloaded or short-circuited; fix it, then reset.");
        case 0xFF:
            return tr("EEPROM checksum error: the stored data are damaged; restore a backup.");
        default:
            return tr("Unknown error state %1").arg(errorState);
    }
}

QString MonitorPage::freshnessText() const {
    return m_freshness->text();
}

QString MonitorPage::stateText() const {
    return m_error->text();
}

void MonitorPage::showStatus(const DeviceStatus& status) {
    m_position->setText(readout(status.positionText, status.position));
    m_speed->setText(readout(status.speedText, status.speed));
    m_program->setText(QString::number(status.activeProgram));
    m_lastErrorState = status.errorState;
    if (!status.outputs.isEmpty()) m_outputs->setStates(status.outputs);
    if (!status.inputs.isEmpty()) m_inputs->setStates(status.inputs);
    showFreshness();
    if (!m_pause->isChecked()) {
        // The time axis counts from the first sample shown (0 s), not from
        // when the page was made.
        if (!m_clock.isValid()) m_clock.start();
        m_trend->addSample(m_clock.elapsed() / 1000.0,
                           plotted(status.positionText, status.position),
                           plotted(status.speedText, status.speed));
    }
    Q_EMIT statusUpdated(status);
}

void MonitorPage::showFreshness() {
    const LiveFreshness* freshness = m_session->freshness();
    const bool live = freshness->isLive();
    const bool known = m_lastErrorState >= 0 && freshness->lastAnswer().isValid();
    QString text;
    switch (freshness->state()) {
        case LiveFreshness::State::NoValues:
            text = m_session->isOnline() ? tr("Waiting for the first answer.")
                                         : tr("Offline: no live values.");
            break;
        case LiveFreshness::State::Live:
            text = tr("Live: last answer at %1.").arg(freshness->lastAnswerText());
            break;
        case LiveFreshness::State::Stale:
            text = known ? tr("No answer since %1. The values below are from then, not live.")
                               .arg(freshness->lastAnswerText())
                         : tr("No answer from the device.");
            break;
        case LiveFreshness::State::Paused:
            text = known ? tr("Not polled: the values below are from %1.")
                               .arg(freshness->lastAnswerText())
                         : tr("Not polled: no live values.");
            break;
    }
    m_freshness->setText(text);
    QPalette pal = palette();
    if (freshness->isStale()) {
        pal.setColor(QPalette::WindowText, QColor(0xd0, 0x40, 0x2e));
        QFont bold = font();
        bold.setBold(true);
        m_freshness->setFont(bold);
    } else {
        m_freshness->setFont(font());
    }
    m_freshness->setPalette(pal);
    // Old values stay readable but are not shown as live.
    for (QWidget* value : {static_cast<QWidget*>(m_position), static_cast<QWidget*>(m_speed),
                           static_cast<QWidget*>(m_program), static_cast<QWidget*>(m_outputs),
                           static_cast<QWidget*>(m_inputs)}) {
        value->setEnabled(live);
        value->setToolTip(known ? tr("Value of %1").arg(freshness->lastAnswerText()) : QString());
    }
    if (!known) {
        m_error->setText(m_session->isOnline() ? tr("unknown") : tr("offline"));
    } else if (live) {
        m_error->setText(errorText(m_lastErrorState));
    } else {
        m_error->setText(tr("unknown now; at %1: %2")
                             .arg(freshness->lastAnswerText(), errorText(m_lastErrorState)));
    }
    m_reset->setEnabled(live && m_lastErrorState > 0);
    if (!live) {
        m_trend->breakLine();
        Q_EMIT liveEnded();
    }
}

}  // namespace cambench
