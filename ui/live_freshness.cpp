#include "live_freshness.h"

#include "clock_time.h"

namespace cambench {

LiveFreshness::LiveFreshness(QObject* parent) : QObject(parent) {}

void LiveFreshness::answered(const QDateTime& at) {
    const bool wasLive = m_state == State::Live;
    m_lastAnswer = at;
    if (wasLive) {
        Q_EMIT changed(m_state);  // still live, with a new time to show
    } else {
        setState(State::Live);
    }
}

void LiveFreshness::missed() {
    if (m_state != State::Stale) setState(State::Stale);
}

void LiveFreshness::paused(const QString& reason) {
    if (m_state == State::NoValues) return;
    if (m_state == State::Paused && m_pauseReason == reason) return;
    m_pauseReason = reason;
    if (m_state == State::Paused)
        Q_EMIT changed(m_state);  // paused for another reason now
    else
        setState(State::Paused);
}

void LiveFreshness::reset() {
    m_lastAnswer = {};
    setState(State::NoValues);
}

void LiveFreshness::setState(State state) {
    if (m_state == state) return;
    m_state = state;
    Q_EMIT changed(state);
}

QString LiveFreshness::lastAnswerText() const {
    return m_lastAnswer.isValid() ? clockTime(m_lastAnswer.time()) : QStringLiteral("—");
}

QString LiveFreshness::describe() const {
    switch (m_state) {
        case State::NoValues:
            return tr("No live values yet");
        case State::Live:
            return tr("Live, last answer %1").arg(lastAnswerText());
        case State::Stale:
            return m_lastAnswer.isValid() ? tr("No answer since %1").arg(lastAnswerText())
                                          : tr("No answer yet");
        case State::Paused:
            return m_pauseReason.isEmpty()
                       ? tr("Not polled now; values of %1").arg(lastAnswerText())
                       : tr("Paused (%1); values of %2").arg(m_pauseReason, lastAnswerText());
    }
    return {};
}

QString LiveFreshness::valueNote() const {
    switch (m_state) {
        case State::NoValues:
            return tr("not read");
        case State::Live:
            return tr("live");
        case State::Stale:
            return m_lastAnswer.isValid() ? tr("no answer since %1").arg(lastAnswerText())
                                          : tr("no answer yet");
        case State::Paused:
            return m_pauseReason.isEmpty()
                       ? tr("paused, read %1").arg(lastAnswerText())
                       : tr("paused (%1), read %2").arg(m_pauseReason, lastAnswerText());
    }
    return {};
}

}  // namespace cambench
