#include "live_device_page.h"

#include "device_session.h"
#include "live_freshness.h"
#include "motion_stop.h"
#include "sentence.h"
#include "stop_button.h"

#include <QDateTime>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>

namespace cambench {

LiveDevicePage::LiveDevicePage(DeviceSession* session, QWidget* parent)
    : SectionPage(parent), m_session(session), m_freshness(new LiveFreshness(this)) {
    connect(m_freshness, &LiveFreshness::changed, this, &LiveDevicePage::showFreshness);
    comm::JobRunner* worker = &session->worker();
    connect(worker, &comm::JobRunner::jobStarted, this, [this](quint64 id) {
        if (id == m_pollJob) m_pollOnLine = true;
    });
    connect(worker, &comm::JobRunner::jobProgress, this, [this](quint64 id) {
        if (id == m_pollJob) m_pollProgress = true;
    });
    connect(worker, &comm::JobRunner::jobFinished, this, [this](quint64 id) {
        // Removed from the queue (a STOP's cancel, a reconnect) without an answer.
        if (id == m_pollJob) m_pollJob = 0;
    });
}

LiveDevicePage::PollState LiveDevicePage::pollState() const {
    if (m_pollJob == 0) return PollState::Idle;
    return m_pollOnLine ? PollState::OnLine : PollState::Queued;
}

void LiveDevicePage::pollMissed() {
    // A long poll (many variables, one telegram each) whose answers keep
    // coming is slow, not silent.
    if (m_pollProgress) {
        m_pollProgress = false;
        return;
    }
    m_freshness->missed();
    m_session->freshness()->missed();
}

void LiveDevicePage::pollPaused(const QString& reason) {
    m_freshness->paused(reason);
    m_session->freshness()->paused(reason);
}

void LiveDevicePage::pollStopped() {
    m_freshness->paused();
}

void LiveDevicePage::lineLost() {
    m_freshness->missed();
    markStale();
}

bool LiveDevicePage::confirm(const QString& title, const QString& question, const QString& detail) {
    QMessageBox box(QMessageBox::Warning, title, question, QMessageBox::Cancel, this);
    box.setObjectName(QStringLiteral("pageConfirm"));
    box.setInformativeText(detail);
    QPushButton* yes = box.addButton(title, QMessageBox::AcceptRole);
    box.setDefaultButton(QMessageBox::Cancel);
    box.exec();
    return box.clickedButton() == yes;
}

void LiveDevicePage::pollAnswered(bool ok) {
    if (ok) {
        const QDateTime now = QDateTime::currentDateTime();
        m_freshness->answered(now);
        m_session->freshness()->answered(now);
    } else {
        m_freshness->missed();
        m_session->freshness()->missed();
    }
}

void LiveDevicePage::addLiveValue(QWidget* widget) {
    m_liveValues << widget;
    showFreshness();
}

QLabel* LiveDevicePage::freshnessLine() {
    if (!m_freshnessLine) {
        m_freshnessLine = new QLabel;
        m_freshnessLine->setObjectName(QStringLiteral("pageFreshness"));
        showFreshness();
    }
    return m_freshnessLine;
}

void LiveDevicePage::showFreshness() {
    const bool live = m_freshness->isLive();
    const QString note = m_freshness->describe();
    for (QWidget* widget : m_liveValues) {
        // Greyed through the palette, not disabled: a greyed value stays
        // selectable and a click on it (an LED) still works. Live: the
        // inherited palette again (so that a switch to dark reaches it).
        widget->setPalette(QPalette());
        if (!live) {
            QPalette palette = widget->palette();
            for (QPalette::ColorRole role : {QPalette::WindowText, QPalette::Text})
                palette.setColor(role, palette.color(QPalette::Disabled, role));
            widget->setPalette(palette);
        }
        widget->setToolTip(live ? QString() : note);
    }
    if (m_reportsMotion && !live) m_session->motionStop()->noteLiveStatusOld(this);
    if (m_freshnessLine) {
        m_freshnessLine->setText(note);
        QFont font = m_freshnessLine->font();
        font.setBold(m_freshness->isStale());
        m_freshnessLine->setFont(font);
    }
    freshnessChanged();
}

void LiveDevicePage::reportMotion(bool moving, bool wholeDevice, const QString& what) {
    m_reportsMotion = true;
    using Motion = MotionStop::Motion;
    m_session->motionStop()->noteLiveStatus(
        this, moving ? Motion::Moving : (wholeDevice ? Motion::Standing : Motion::Unknown), what);
}

void LiveDevicePage::reportMotionSent(const QString& what) {
    m_session->motionStop()->noteMotionSent(what);
}

QLabel* LiveDevicePage::resultLine() {
    if (!m_result) {
        m_result = new QLabel;
        m_result->setObjectName(QStringLiteral("pageResult"));
        m_result->setWordWrap(true);
        m_result->setTextInteractionFlags(Qt::TextSelectableByMouse);
    }
    return m_result;
}

QPushButton* LiveDevicePage::makeShellStop(const QString& objectName, const QString& toolTip,
                                           std::function<void()> armedChanged) {
    auto* button = new QPushButton(tr("STOP (Esc)"), this);
    button->setObjectName(objectName);
    button->setToolTip(toolTip);
    routeToShellStop(
        button, m_session->motionStop(), this,
        [this](const QString& text, bool ok) {
            showResult(text, ok);
            poll();
        },
        std::move(armedChanged));
    return button;
}

void LiveDevicePage::stopAll() {
    m_session->motionStop()->stopAll();
}

void LiveDevicePage::clearResult() {
    if (!m_result) return;
    m_result->clear();
    m_result->setStyleSheet(QString());
}

void LiveDevicePage::forgetDevice() {
    clearResult();
    markStale();
}

void LiveDevicePage::showResult(const QString& text, bool ok) {
    // The line starts a sentence, also when it is a message from comm/
    // ("no reply from the drive") shown as it came.
    const QString sentence = capitalised(text);
    resultLine()->setText(sentence);
    resultLine()->setStyleSheet(ok ? QString() : QStringLiteral("color: #d03030;"));
    Q_EMIT statusMessage(sentence);
}

}  // namespace cambench
