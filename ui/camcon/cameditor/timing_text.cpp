#include "ui/camcon/cameditor/timing_text.h"

#include <QCoreApplication>
#include <QLocale>

namespace cambench {

namespace {

struct TimingText {
    Q_DECLARE_TR_FUNCTIONS(TimingText)
};

}  // namespace

QString speedText(double positionsPerSecond, const Axis& axis) {
    const double speed = fromPositionsPerSecond(positionsPerSecond, axis);
    return TimingText::tr("%1 %2").arg(QLocale().toString(speed, 'f', speed >= 100 ? 0 : 1),
                                       speedUnit(axis));
}

QString durationText(double milliseconds) {
    if (milliseconds >= 1000)
        return TimingText::tr("%1 s").arg(QLocale().toString(milliseconds / 1000, 'f', 2));
    return TimingText::tr("%1 ms").arg(
        QLocale().toString(milliseconds, 'f', milliseconds >= 100 ? 0 : 1));
}

QString timingProblemText(int output, const TimingProblem& problem, const Axis& axis) {
    const QString where = problem.fromSpeed > 0
                              ? TimingText::tr("above %1").arg(speedText(problem.fromSpeed, axis))
                              : TimingText::tr("at every speed");
    switch (problem.kind) {
        case TimingProblem::Kind::Vanishes:
            return TimingText::tr(
                       "Output %1: cam %2 vanishes %3 (the switch-off dead time is longer than "
                       "the switch-on one).")
                .arg(output)
                .arg(problem.cam)
                .arg(where);
        case TimingProblem::Kind::Merges:
            return TimingText::tr("Output %1: cams %2 and %3 merge %4.")
                .arg(output)
                .arg(problem.cam)
                .arg(problem.nextCam)
                .arg(where);
        case TimingProblem::Kind::ShortPulse:
            return TimingText::tr("Output %1: cam %2 is on for less than the minimum pulse %3.")
                .arg(output)
                .arg(problem.cam)
                .arg(where);
        case TimingProblem::Kind::ShiftOverCycle:
            return TimingText::tr("Output %1: the switch points move by more than one cycle %2.")
                .arg(output)
                .arg(where);
    }
    return {};
}

}  // namespace cambench
