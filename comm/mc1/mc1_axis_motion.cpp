#include "mc1_axis_motion.h"

#include "mc1_controller.h"

#include <QCoreApplication>

namespace cambench::comm {

namespace {

// The maximum ramp: STOP of everything is for when something goes wrong.
constexpr Mc1AxisCommand kStop = Mc1AxisCommand::QuickStop;

}  // namespace

MotionStopReport Mc1AxisMotion::stopAllMotion() {
    MotionStopReport report;
    if (const Result<Mc1Variant> identified = m_controller.ensureIdentified(); !identified) {
        report.lines << MotionStopLine{
            QCoreApplication::translate("cambench::comm", "Controller"), false,
            QCoreApplication::translate("cambench::comm", "no stop was sent: %1")
                .arg(identified.error().message)};
        return report;
    }
    // The axes it has; when they cannot be read, every logical axis (a
    // refusal then may only mean that the axis does not exist).
    const Result<Mc1Axes> axes = m_controller.axes();
    QList<int> numbers = axes ? axes->numbers : QList<int>();
    if (!axes)
        for (int axis = kMc1FirstAxis; axis <= kMc1LastAxis; ++axis) numbers << axis;
    // Every stop first, one attempt each, no read between.
    QList<Status> sent;
    for (int axis : numbers) sent << m_controller.sendAxisCommand(axis, kStop, 0, 1);
    // Then the ones whose answer was lost, as often as their repeat rule allows.
    if (mc1AxisCommandRetry(kStop) != Mc1Retry::Never)
        for (int i = 0; i < numbers.size(); ++i)
            if (!sent.at(i) && sent.at(i).error().kind == ErrorKind::Communication)
                sent[i] = m_controller.sendAxisCommand(numbers.at(i), kStop, 0);
    // Read-backs last: they say what the axes do, never whether the stop went.
    for (int i = 0; i < numbers.size(); ++i) {
        const int axis = numbers.at(i);
        const Result<Mc1AxisState> state = m_controller.axisState(axis);
        const QString found = state ? state->summary()
                                    : QCoreApplication::translate(
                                          "cambench::comm", "reading the axis back failed: %1")
                                          .arg(state.error().message);
        MotionStopLine line{QCoreApplication::translate("cambench::comm", "Axis %1").arg(axis),
                            sent.at(i).ok(), found};
        if (!line.acknowledged) {
            QString why = sent.at(i).error().message;
            if (!axes && isMc1Refusal(sent.at(i).error()))
                why += QCoreApplication::translate(
                           "cambench::comm",
                           " (the controller's axes could not be read: %1; it may have no axis %2)")
                           .arg(axes.error().message)
                           .arg(axis);
            line.detail = QCoreApplication::translate("cambench::comm", "not acknowledged: %1; %2")
                              .arg(why, found);
        }
        report.lines << line;
    }
    if (report.lines.isEmpty())
        report.lines << MotionStopLine{
            QCoreApplication::translate("cambench::comm", "Controller"), true,
            QCoreApplication::translate("cambench::comm",
                                        "the controller has no axes (%1): nothing to stop")
                .arg(axes ? axes->source : QString())};
    return report;
}

Result<QStringList> Mc1AxisMotion::activeMotion() {
    const Result<Mc1Axes> axes = m_controller.axes();
    if (!axes) return axes.error();
    QStringList moving;
    for (int axis : axes->numbers) {
        const Result<Mc1AxisState> state = m_controller.axisState(axis);
        if (!state) return state.error();
        if (state->moving)
            moving << (state->provisional
                           ? QCoreApplication::translate(
                                 "cambench::comm", "axis %1 moves (provisional parameter numbers)")
                           : QCoreApplication::translate("cambench::comm", "axis %1 moves"))
                          .arg(axis);
    }
    return moving;
}

}  // namespace cambench::comm
