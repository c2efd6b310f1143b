#include "mc1_axis_motion.h"

#include "mc1_controller.h"
#include "mc1_parameters.h"

#include <QCoreApplication>

namespace cambench::comm {

namespace {

// The maximum ramp: STOP of everything is for when something goes wrong.
constexpr Mc1AxisCommand kStop = Mc1AxisCommand::QuickStop;

// Every axis an MC-1 can have: only the MC200 V2 has axis telegrams, and
// its logical axes are 1 to 8.
QList<int> everyPossibleAxis() {
    QList<int> numbers;
    for (int axis = kMc1FirstAxis; axis <= kMc1LastAxis; ++axis) numbers << axis;
    return numbers;
}

QString axisName(int axis) {
    return QCoreApplication::translate("cambench::comm", "Axis %1").arg(axis);
}

}  // namespace

MotionStopReport Mc1AxisMotion::stopAllMotion() {
    // Nothing before the stops: no probe, no RDTABLE. The axes known (given,
    // or found earlier) get a stop each; unknown, every axis there can be,
    // and an axis that is not there refuses its stop.
    const std::optional<Mc1Axes> known = m_controller.knownAxes();
    const QList<int> numbers = known ? known->numbers : everyPossibleAxis();
    // Every stop first, one attempt each, no read between.
    QList<Status> sent;
    for (int axis : numbers) sent << m_controller.sendAxisCommand(axis, kStop, 0, 1);
    // Then the ones whose answer was lost, as often as their repeat rule allows.
    if (mc1AxisCommandRetry(kStop) != Mc1Retry::Never)
        for (int i = 0; i < numbers.size(); ++i)
            if (!sent.at(i) && sent.at(i).error().kind == ErrorKind::Communication)
                sent[i] = m_controller.sendAxisCommand(numbers.at(i), kStop, 0);
    // Read-backs last: they say what the axes do, never whether the stop went.
    MotionStopReport report;
    for (int i = 0; i < numbers.size(); ++i) {
        const int axis = numbers.at(i);
        if (!known && !sent.at(i) && isMc1Refusal(sent.at(i).error())) {
            // Asked blind: the controller says it has no such axis.
            MotionStopLine absent{
                axisName(axis), false,
                QCoreApplication::translate("cambench::comm",
                                            "no such axis: the controller refused its stop")};
            absent.absent = true;  // named: a positional true was nothingToStop once
            report.lines << absent;
            continue;
        }
        const Result<Mc1AxisState> state = m_controller.axisState(axis);
        const QString found = state ? state->summary()
                                    : QCoreApplication::translate(
                                          "cambench::comm", "reading the axis back failed: %1")
                                          .arg(state.error().message);
        MotionStopLine line{axisName(axis), sent.at(i).ok(), found};
        if (!line.acknowledged)
            line.detail = QCoreApplication::translate("cambench::comm", "not acknowledged: %1; %2")
                              .arg(sent.at(i).error().message, found);
        report.lines << line;
    }
    if (report.lines.isEmpty())
        report.lines << MotionStopLine{
            QCoreApplication::translate("cambench::comm", "Controller"), true,
            QCoreApplication::translate("cambench::comm",
                                        "the controller has no axes (%1): nothing to stop")
                .arg(known ? known->source : QString())};
    return report;
}

Result<QStringList> Mc1AxisMotion::activeMotion() {
    const Result<Mc1Axes> axes = m_controller.axes();
    if (!axes) return axes.error();
    QStringList moving;
    QStringList guessed;  // "not moving", read through numbers that are a guess
    for (int axis : axes->numbers) {
        const Result<Mc1AxisState> state = m_controller.axisState(axis);
        if (!state) return state.error();
        if (state->moving)
            moving << (state->provisional
                           ? QCoreApplication::translate(
                                 "cambench::comm", "axis %1 moves (provisional parameter numbers)")
                           : QCoreApplication::translate("cambench::comm", "axis %1 moves"))
                          .arg(axis);
        else if (state->provisional)
            guessed << QString::number(axis);
    }
    // A guess is never "nothing moves": what it says may be another value.
    if (!guessed.isEmpty())
        return Error::invalidData(
            QCoreApplication::translate(
                "cambench::comm",
                "could not tell whether axis %1 moves: its status was read through CamBench's "
                "guessed parameter numbers (provisional), not the controller's; load the "
                "controller's parameter table%2")
                .arg(guessed.join(QStringLiteral(", ")),
                     moving.isEmpty()
                         ? QString()
                         : QCoreApplication::translate("cambench::comm", " (besides: %1)")
                               .arg(moving.join(QStringLiteral(", ")))));
    return moving;
}

}  // namespace cambench::comm
