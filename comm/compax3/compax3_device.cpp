#include "compax3_device.h"

#include <QCoreApplication>

#include <tuple>

namespace cambench::comm {

QString Compax3DriveStatus::summary() const {
    const QString at = compax3NumberText(position);
    if (status.powerless())
        return QCoreApplication::translate("cambench::comm", "powerless at %1").arg(at);
    if (moving()) return QCoreApplication::translate("cambench::comm", "moving, now at %1").arg(at);
    return QCoreApplication::translate("cambench::comm", "powered, standing at %1 (last set %2)")
        .arg(at)
        .arg(lastSet);
}

QString Compax3SetValues::modeText() const {
    if (mode == 1) return QCoreApplication::translate("cambench::comm", "absolute");
    if (mode == 2) return QCoreApplication::translate("cambench::comm", "relative");
    return QCoreApplication::translate("cambench::comm", "mode %1").arg(mode);
}

QStringList Compax3SetValues::changesTo(const Compax3SetValues& now) const {
    QStringList changes;
    const std::tuple<QString, double, double> numbers[] = {
        {QCoreApplication::translate("cambench::comm", "target"), target, now.target},
        {QCoreApplication::translate("cambench::comm", "velocity"), velocity, now.velocity},
        {QCoreApplication::translate("cambench::comm", "acceleration"), acceleration,
         now.acceleration},
        {QCoreApplication::translate("cambench::comm", "deceleration"), deceleration,
         now.deceleration}};
    for (const auto& [name, was, is] : numbers)
        if (was != is)
            changes << QStringLiteral("%1 %2 → %3")
                           .arg(name, compax3NumberText(was), compax3NumberText(is));
    if (mode != now.mode)
        changes << QCoreApplication::translate("cambench::comm", "mode %1 → %2")
                       .arg(modeText(), now.modeText());
    return changes;
}

QString Compax3CommandResult::summary() const {
    if (after) return after->summary();
    return QCoreApplication::translate("cambench::comm",
                                       "the state could not be read back afterwards: %1")
        .arg(readBackFailed);
}

QString compax3MotionText(Compax3Motion motion) {
    switch (motion) {
        case Compax3Motion::Enable:
            return QCoreApplication::translate("cambench::comm",
                                               "power the axis and acknowledge errors");
        case Compax3Motion::Disable:
            return QCoreApplication::translate("cambench::comm", "switch the axis powerless");
        case Compax3Motion::JogPlus:
            return QCoreApplication::translate("cambench::comm", "jog the axis in + direction");
        case Compax3Motion::JogMinus:
            return QCoreApplication::translate("cambench::comm", "jog the axis in − direction");
        case Compax3Motion::Stop:
            return QCoreApplication::translate("cambench::comm", "stop the axis");
    }
    return {};
}

QString compax3SetMoveText(const Compax3SetMove& move) {
    QStringList parts;
    if (move.target)
        parts << QCoreApplication::translate("cambench::comm", "target %1")
                     .arg(compax3NumberText(*move.target));
    if (move.velocity)
        parts << QCoreApplication::translate("cambench::comm", "velocity %1")
                     .arg(compax3NumberText(*move.velocity));
    if (move.acceleration)
        parts << QCoreApplication::translate("cambench::comm", "acceleration %1")
                     .arg(compax3NumberText(*move.acceleration));
    if (move.deceleration)
        parts << QCoreApplication::translate("cambench::comm", "deceleration %1")
                     .arg(compax3NumberText(*move.deceleration));
    const QString what =
        move.set == 0 ? QCoreApplication::translate("cambench::comm", "start homing (set 0)")
                      : QCoreApplication::translate("cambench::comm", "start set %1").arg(move.set);
    if (parts.isEmpty()) return what;
    return QStringLiteral("%1 (%2)").arg(what, parts.join(QStringLiteral(", ")));
}

bool compax3MotionMoves(Compax3Motion motion) {
    return motion == Compax3Motion::JogPlus || motion == Compax3Motion::JogMinus;
}

Result<DeviceIdentity> Compax3Device::readIdentity() {
    const Result<Compax3Identity> drive = identity();
    if (!drive) return drive.error();
    return drive->deviceIdentity();
}

}  // namespace cambench::comm
