#include "program_stop.h"

#include "dialog_stop.h"
#include "shell_log.h"
#include "stop_shortcut.h"

#include <QCoreApplication>

namespace cambench {

ProgramStop& ProgramStop::instance() {
    static QPointer<ProgramStop> program;
    if (!program) program = new ProgramStop(QCoreApplication::instance());
    return *program;
}

ProgramStop::ProgramStop(QObject* parent) : StopControl(parent) {
    // A platform's own file dialog runs outside Qt's event loop: Escape in
    // it would never reach the STOP key, and it gets no STOP button.
    QCoreApplication::setAttribute(Qt::AA_DontUseNativeDialogs);
    new StopShortcut(this, this);
    new DialogStops(this, this);
}

void ProgramStop::add(StopControl* stop) {
    if (m_stops.contains(stop)) return;
    m_stops.append(stop);
    connect(stop, &StopControl::availabilityChanged, this, &StopControl::availabilityChanged);
    connect(stop, &QObject::destroyed, this, [this] {
        m_stops.removeAll(nullptr);
        Q_EMIT availabilityChanged();
    });
    Q_EMIT availabilityChanged();
}

bool ProgramStop::available() const {
    for (const QPointer<StopControl>& stop : m_stops)
        if (stop && stop->available()) return true;
    return false;
}

bool ProgramStop::armed() const {
    for (const QPointer<StopControl>& stop : m_stops)
        if (stop && stop->armed()) return true;
    return false;
}

void ProgramStop::stopAll() {
    if (!available()) return;
    qCInfo(shellLog) << "program STOP";
    delete m_round;  // pressed again: sent again, the answers before no longer count
    QList<StopRound::Member> members;
    // Each window's STOP, also one whose device is not on the line: it
    // reports that as not reached.
    for (const QPointer<StopControl>& stop : m_stops)
        if (StopControl* control = stop; control && control->available())
            members.append({QString(), control, true, [control] { control->stopAll(); }});
    Q_EMIT stopStarted();
    m_round = StopRound::start(this, members, [this](const QList<StopRound::Answer>& answers) {
        comm::MotionStopReport report;
        for (const StopRound::Answer& answer : answers) report.lines << answer.report.lines;
        finishStop(report);
    });
}

}  // namespace cambench
