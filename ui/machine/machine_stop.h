#pragma once

#include "ui/stop_control.h"
#include "ui/stop_round.h"

#include <QList>
#include <QPointer>
#include <QStringList>

namespace cambench {

class MotionStop;

// The STOP of a machine: every STOP on screen and the STOP key of the
// machine's window stop every device of the machine that can move, each
// through its own STOP (its own worker, at once, in parallel: no device
// waits for another's answer), nothing retried. The report has one line
// per axis or drive, named by its device; a device that can move but is
// not on the line is named as not reached.
class MachineStop : public StopControl {
    Q_OBJECT
public:
    explicit MachineStop(QObject* parent = nullptr);

    // `stop` (a device's own) hands its STOPs to this one from now on.
    void addDevice(const QString& name, MotionStop* stop);

    bool available() const override;
    bool armed() const override;
    void stopAll() override;
    bool stopRunning() const { return m_round && !m_round->isDone(); }

    // The last STOP for the status bar: which devices were stopped, which
    // did not acknowledge, which could not be reached.
    QString lastSummary() const { return m_summary; }

private:
    struct Member {
        QString name;
        QPointer<MotionStop> stop;
    };
    void finishRound(const QList<StopRound::Answer>& answers);

    QList<Member> m_members;
    QPointer<StopRound> m_round;  // the running STOP's answers
    QString m_summary;
};

}  // namespace cambench
