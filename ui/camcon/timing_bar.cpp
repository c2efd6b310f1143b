#include "timing_bar.h"

#include "workspace.h"

#include "ui/camcon/cameditor/cam_diagram_widget.h"
#include "ui/camcon/cameditor/cam_document.h"
#include "ui/camcon/cameditor/cam_editor_widget.h"
#include "ui/camcon/cameditor/editor_colors.h"
#include "ui/camcon/cameditor/timing_text.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace cambench {

namespace {

constexpr int kSliderSteps = 1000;
constexpr double kDefaultRotaryTop = 1000.0;  // 1/min
constexpr double kLinearAxisLengthsPerSecond = 10.0;

}  // namespace

TimingBar::TimingBar(Workspace* workspace, CamEditorWidget* editor, QWidget* parent)
    : QWidget(parent),
      m_workspace(workspace),
      m_editor(editor),
      m_show(new QCheckBox(this)),
      m_speed(new QDoubleSpinBox(this)),
      m_slider(new QSlider(Qt::Horizontal, this)),
      m_follow(new QCheckBox(this)),
      m_summary(new QLabel(this)) {
    setObjectName(QStringLiteral("timingBar"));
    m_show->setObjectName(QStringLiteral("timingShow"));
    m_speed->setObjectName(QStringLiteral("timingSpeed"));
    m_follow->setObjectName(QStringLiteral("timingFollow"));
    m_summary->setObjectName(QStringLiteral("timingSummary"));
    m_speed->setDecimals(1);
    m_speed->setRange(0, 1e7);
    m_speed->setValue(100);
    m_speed->setKeyboardTracking(false);
    m_slider->setRange(0, kSliderSteps);
    m_slider->setMinimumWidth(120);
    m_follow->setEnabled(false);
    m_summary->setTextFormat(Qt::PlainText);
    m_summary->setWordWrap(true);
    m_summary->hide();

    // The controls on one line, what they show (often a long warning) on
    // the next, whole.
    auto* controls = new QHBoxLayout;
    controls->addWidget(m_show);
    controls->addWidget(m_speed);
    controls->addWidget(m_slider, 1);
    controls->addWidget(m_follow);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 0, 4, 0);
    layout->setSpacing(2);
    layout->addLayout(controls);
    layout->addWidget(m_summary);

    connect(m_show, &QCheckBox::toggled, this, &TimingBar::recompute);
    connect(m_speed, &QDoubleSpinBox::valueChanged, this, [this] {
        updateSlider();
        recompute();
    });
    connect(m_slider, &QSlider::sliderMoved, this, [this](int step) {
        // A speed chosen by hand is no longer the device's.
        setFollowDevice(false);
        m_liveLost = false;
        m_speed->setValue(sliderTop() * step / kSliderSteps);
    });
    connect(m_speed, &QDoubleSpinBox::editingFinished, this, [this] {
        if (!m_speed->hasFocus()) return;
        setFollowDevice(false);
        m_liveLost = false;
        recompute();
    });
    connect(m_follow, &QCheckBox::toggled, this, [this](bool on) {
        if (on) m_liveLost = false;
        if (on && m_liveSpeed) m_speed->setValue(fromPositionsPerSecond(*m_liveSpeed, axis()));
        recompute();
    });

    CamDocument* cams = workspace->cams();
    connect(cams, &CamDocument::trackChanged, this, &TimingBar::recompute);
    connect(cams, &CamDocument::programChanged, this, &TimingBar::recompute);
    connect(cams, &CamDocument::deadTimeChanged, this, &TimingBar::recompute);
    connect(cams, &CamDocument::minimumPulsesChanged, this, &TimingBar::recompute);
    connect(cams, &CamDocument::limitsChanged, this, [this] {
        retranslate();
        recompute();
    });
    // Dead-time modes edited or read, settings read: all end here.
    connect(workspace, &Workspace::changedCountChanged, this, &TimingBar::recompute);
    connect(workspace, &Workspace::settingsChanged, this, &TimingBar::updateSlider);
    connect(editor, &CamEditorWidget::currentProgramChanged, this, &TimingBar::recompute);
    retranslate();
    updateSlider();
    recompute();
}

bool TimingBar::timingShown() const {
    return m_show->isChecked();
}

void TimingBar::setTimingShown(bool shown) {
    m_show->setChecked(shown);
}

double TimingBar::speed() const {
    return m_speed->value();
}

void TimingBar::setSpeed(double speed) {
    m_speed->setValue(speed);
}

void TimingBar::setFollowDevice(bool follow) {
    m_follow->setChecked(follow && m_follow->isEnabled());
}

void TimingBar::setLiveSpeed(std::optional<double> positionsPerSecond) {
    const bool wasLive = m_liveSpeed.has_value();
    m_liveSpeed = positionsPerSecond;
    m_follow->setEnabled(m_liveSpeed.has_value());
    if (!m_liveSpeed) {
        if (m_follow->isChecked()) {
            // Never show a stale speed as the device's: say it stopped.
            const QSignalBlocker blocker(m_follow);
            m_follow->setChecked(false);
            m_liveLost = true;
            recompute();
        }
        return;
    }
    if (m_follow->isChecked()) {
        m_speed->setValue(fromPositionsPerSecond(*m_liveSpeed, axis()));
    } else if (!wasLive) {
        retranslate();
    }
}

Axis TimingBar::axis() const {
    return m_workspace->cams()->axis();
}

double TimingBar::sliderTop() const {
    double top =
        axis().rotary ? kDefaultRotaryTop : kLinearAxisLengthsPerSecond * double(axis().span());
    if (m_workspace->settings().known()) {
        bool ok = false;
        const double hundredPercent = m_workspace->settings()
                                          .value(QStringLiteral("speed100Percent"))
                                          .value_or(QVariant())
                                          .toDouble(&ok);
        if (ok && hundredPercent > 0) top = hundredPercent;
    }
    return std::max(top, m_speed->value());
}

void TimingBar::updateSlider() {
    const QSignalBlocker blocker(m_slider);
    m_slider->setValue(int(std::lround(m_speed->value() / sliderTop() * kSliderSteps)));
}

void TimingBar::recompute() {
    CamDiagramWidget* diagram = m_editor->diagram();
    m_speed->setEnabled(m_show->isChecked());
    m_slider->setEnabled(m_show->isChecked());
    if (!m_show->isChecked()) {
        m_timing.clear();
        diagram->clearTiming();
        m_summary->clear();
        m_summary->hide();
        Q_EMIT timingChanged();
        return;
    }
    const CamDocument* cams = m_workspace->cams();
    const Axis a = axis();
    const double v = toPositionsPerSecond(m_speed->value(), a);
    m_timing = timeProgram(cams->program(m_editor->currentProgram()),
                           deadTimesAsModes(cams->deadTimes(), m_workspace->shownDeadTimeModes()),
                           v, a, cams->minimumPulses());
    diagram->setTiming(m_timing, speedText(v, a));
    const QString text = summary();
    m_summary->setText(text);
    m_summary->setVisible(true);
    m_summary->setToolTip(text);
    bool warned = false;
    for (const OutputTiming& timing : m_timing) warned = warned || !timing.problems.isEmpty();
    QPalette palette = m_summary->palette();
    palette.setColor(QPalette::WindowText,
                     warned ? errorColor() : this->palette().color(QPalette::WindowText));
    m_summary->setPalette(palette);
    Q_EMIT timingChanged();
}

QString TimingBar::summary() const {
    if (!m_show->isChecked()) return {};
    const Axis a = axis();
    const QString at = speedText(toPositionsPerSecond(m_speed->value(), a), a);
    QString text;
    if (m_timing.isEmpty()) {
        text = tr("Program %1 has no cams.").arg(m_editor->currentProgram());
    } else {
        QStringList problems;
        std::optional<std::pair<int, TimingProblem>> first;
        for (const OutputTiming& timing : m_timing) {
            for (const TimingProblem& problem : timing.problems)
                problems << timingProblemText(timing.output, problem, a);
            if (timing.firstLimit &&
                (!first || timing.firstLimit->fromSpeed < first->second.fromSpeed))
                first = std::make_pair(timing.output, *timing.firstLimit);
        }
        if (!problems.isEmpty()) {
            text = tr("At %1: %n warning(s). %2", nullptr, int(problems.size()))
                       .arg(at, problems.join(QLatin1Char(' ')));
        } else if (first) {
            text = tr("At %1 every cam switches as drawn. First limit: %2")
                       .arg(at, timingProblemText(first->first, first->second, a));
        } else {
            text = tr("At %1 every cam switches as drawn, at any speed.").arg(at);
        }
    }
    if (m_liveLost)
        text = tr("The device's speed is no longer live; shown at the last speed read.") +
               QLatin1Char(' ') + text;
    return text;
}

void TimingBar::retranslate() {
    m_show->setText(tr("Timing at speed"));
    m_show->setToolTip(
        tr("Draws under every output where it really switches at this speed: the device "
           "switches each edge early by speed × dead time so that the actuator acts at the "
           "programmed position. Durations in ms; warnings where cams vanish, merge or are "
           "shorter than the output's minimum pulse (track table)."));
    m_speed->setSuffix(QLatin1Char(' ') + speedUnit(axis()));
    m_follow->setText(tr("Device speed"));
    m_follow->setToolTip(m_liveSpeed ? tr("Follow the speed the device measures, live.")
                                     : tr("The device's speed is shown while the monitor reads "
                                          "it live (connected, Monitor or diagram polling)."));
}

void TimingBar::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        recompute();
    }
    QWidget::changeEvent(event);
}

}  // namespace cambench
