#pragma once

#include "comm/device/motion_control.h"

#include <QList>
#include <QObject>
#include <QString>

#include <functional>

namespace cambench {

class StopControl;

// One STOP sent to several StopControls at once (a machine's devices, the
// program's windows): each is started at once and answers on its own
// (stopFinished), nobody waits for another; `finished` gets every answer
// when each one reached has answered - at once when none could be reached.
// Deleting the round (a STOP pressed again) drops the answers still due.
class StopRound : public QObject {
    Q_OBJECT
public:
    struct Member {
        QString name;
        StopControl* control = nullptr;  // whose stopFinished answers
        bool reached = false;            // false: not started, said as not reached
        std::function<void()> start;     // sends its STOP
    };
    struct Answer {
        QString name;
        bool reached = false;
        bool answered = false;
        comm::MotionStopReport report;
    };
    using Finished = std::function<void(const QList<Answer>& answers)>;

    // The round, owned by `parent`; it deletes itself once finished.
    static StopRound* start(QObject* parent, const QList<Member>& members, Finished finished);

    bool isDone() const { return m_done; }

private:
    StopRound(QObject* parent, Finished finished);
    void finishIfAllAnswered();

    QList<Answer> m_answers;
    Finished m_finished;
    bool m_done = false;
};

}  // namespace cambench
