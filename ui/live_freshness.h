#pragma once

#include <QDateTime>
#include <QObject>

namespace cambench {

// How old the live values (monitor, cam diagram, connection indicator) are.
// Counted in poll cycles, not in seconds: a cycle that starts while the
// previous poll is still unanswered, or a poll that fails, makes the values
// stale at once; the next answer makes them live again. Nothing here looks
// at a clock except to stamp the answers with their time.
class LiveFreshness : public QObject {
    Q_OBJECT
public:
    enum class State {
        NoValues,  // nothing polled yet on this connection
        Live,      // the last poll cycle was answered
        Stale,     // a poll cycle went by without an answer
        Paused,    // not polled (no page shows live values, or offline)
    };

    explicit LiveFreshness(QObject* parent = nullptr);

    State state() const { return m_state; }
    bool isStale() const { return m_state == State::Stale; }
    bool isLive() const { return m_state == State::Live; }
    // When the last answer arrived (invalid before the first one).
    QDateTime lastAnswer() const { return m_lastAnswer; }

    void answered(const QDateTime& at);
    // A poll came back with an error, or a cycle found the last one unanswered.
    void missed();
    // Not polled now. `reason` names what holds the line ("Back up
    // controller") when polling waits for a long job; empty: the values'
    // page is not shown or the line is offline.
    void paused(const QString& reason = {});
    // A new connection: values of the old one mean nothing.
    void reset();

    // "12:03:04" of the last answer, or "—".
    QString lastAnswerText() const;
    // One line for the monitor and the indicator, e.g. "No answer since 12:03:04".
    QString describe() const;
    // A few words beside a value: "live", "no answer since 12:03:04",
    // "paused (Back up controller), read 12:03:04", "not read".
    QString valueNote() const;

Q_SIGNALS:
    void changed(cambench::LiveFreshness::State state);

private:
    void setState(State state);

    State m_state = State::NoValues;
    QDateTime m_lastAnswer;
    QString m_pauseReason;
};

}  // namespace cambench
