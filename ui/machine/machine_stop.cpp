#include "machine_stop.h"

#include "ui/motion_stop.h"
#include "ui/shell_log.h"

namespace cambench {

MachineStop::MachineStop(QObject* parent) : StopControl(parent) {}

void MachineStop::addDevice(const QString& name, MotionStop* stop) {
    m_members.append({name, stop});
    stop->joinMachine(this);
    connect(stop, &StopControl::availabilityChanged, this, &StopControl::availabilityChanged);
    Q_EMIT availabilityChanged();
}

bool MachineStop::available() const {
    for (const Member& member : m_members)
        if (member.stop && member.stop->available()) return true;
    return false;
}

bool MachineStop::armed() const {
    for (const Member& member : m_members)
        if (member.stop && member.stop->armed()) return true;
    return false;
}

void MachineStop::stopAll() {
    // Every device first, each its own generation: no motion asked before
    // now leaves on any line, whatever STOP runs first.
    for (const Member& member : m_members)
        if (member.stop) member.stop->raiseStopGeneration();
    if (!available()) return;
    qCInfo(shellLog) << "machine STOP pressed";
    // A STOP pressed again while one runs is sent again (never held back);
    // the answers of the one before no longer count.
    delete m_round;
    QList<StopRound::Member> members;
    for (const Member& member : m_members) {
        MotionStop* stop = member.stop;
        if (!stop || !stop->available()) continue;
        // Each device's STOP runs on its own worker; its answer comes when
        // that device has acknowledged, whatever the others do.
        members.append({member.name, stop, stop->armed(), [stop] { stop->stopThisDevice(); }});
    }
    Q_EMIT stopStarted();
    m_round = StopRound::start(
        this, members, [this](const QList<StopRound::Answer>& answers) { finishRound(answers); });
}

void MachineStop::finishRound(const QList<StopRound::Answer>& answers) {
    comm::MotionStopReport report;
    QStringList stopped;
    QStringList notAcknowledged;
    QStringList notReached;
    for (const StopRound::Answer& answer : answers) {
        if (!answer.reached) {
            notReached << answer.name;
            report.lines << comm::MotionStopLine{answer.name, false,
                                                 tr("not connected: the STOP was not sent")};
            continue;
        }
        (answer.report.allAcknowledged() ? stopped : notAcknowledged) << answer.name;
        for (comm::MotionStopLine line : answer.report.lines) {
            line.what = QStringLiteral("%1: %2").arg(answer.name, line.what);
            report.lines << line;
        }
    }
    QStringList parts;
    const QString separator = QStringLiteral(", ");
    if (!stopped.isEmpty()) parts << tr("acknowledged by %1").arg(stopped.join(separator));
    if (!notAcknowledged.isEmpty())
        parts << tr("NOT acknowledged by %1 – use the machine's emergency stop")
                     .arg(notAcknowledged.join(separator));
    if (!notReached.isEmpty())
        parts << tr("could not reach %1 – use the machine's emergency stop")
                     .arg(notReached.join(separator));
    m_summary = parts.join(QStringLiteral("; ")) + QLatin1Char('.');
    qCInfo(shellLog) << "machine STOP done:" << m_summary;
    finishStop(report);
}

}  // namespace cambench
