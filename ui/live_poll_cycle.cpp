#include "live_poll_cycle.h"

#include "device_session.h"
#include "live_device_page.h"

namespace cambench {

LivePollCycle::LivePollCycle(DeviceSession* session, int intervalMs, QObject* parent)
    : QObject(parent), m_session(session) {
    m_timer.setInterval(intervalMs);
    connect(&m_timer, &QTimer::timeout, this, &LivePollCycle::tick);
    connect(&session->worker(), &comm::JobRunner::jobStarted, this,
            [this](quint64, const QString& title) { m_lineJob = title; });
}

void LivePollCycle::setShown(LiveDevicePage* page) {
    if (m_shown == page) return;
    if (m_shown) m_shown->pollStopped();
    m_shown = page;
    if (!m_shown) {
        m_timer.stop();
        return;
    }
    if (m_session->isOnline()) m_shown->poll();
    m_timer.start();
}

void LivePollCycle::tick() {
    if (!m_shown || !m_session->isOnline()) return;
    switch (m_shown->pollState()) {
        case LiveDevicePage::PollState::Idle:
            m_shown->poll();
            break;
        case LiveDevicePage::PollState::OnLine:
            m_shown->pollMissed();
            break;
        case LiveDevicePage::PollState::Queued:
            m_shown->pollPaused(m_lineJob);
            break;
    }
}

}  // namespace cambench
