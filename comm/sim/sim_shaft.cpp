#include "sim_shaft.h"

#include <QHash>
#include <QMutexLocker>
#include <QStringList>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace cambench::comm {

namespace {

// Whether `end` lies ahead of `position` in the direction of `velocity`:
// only then does the motion stop there.
bool endAhead(const SimShaftMotion& motion) {
    if (!motion.end) return false;
    return motion.velocity > 0 ? *motion.end >= motion.position : *motion.end <= motion.position;
}

Error badKey(const QString& port, const QString& what) {
    return Error::usage(QStringLiteral("Simulator port \"%1\": %2").arg(port, what));
}

}  // namespace

double SimShaftMotion::positionAfter(double seconds) const {
    const double travelled = position + velocity * std::max(0.0, seconds);
    if (velocity == 0.0 || !endAhead(*this)) return travelled;
    return velocity > 0 ? std::min(travelled, *end) : std::max(travelled, *end);
}

SimShaft::SimShaft(Clock clock) : m_clock(std::move(clock)) {
    m_publishedMs = now();
}

qint64 SimShaft::now() const {
    if (m_clock) return m_clock();
    return std::chrono::duration_cast<std::chrono::milliseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

int SimShaft::takeDrive() {
    QMutexLocker lock(&m_mutex);
    return ++m_driver;
}

void SimShaft::publish(int token, const SimShaftMotion& motion) {
    QMutexLocker lock(&m_mutex);
    if (token != m_driver) return;
    m_motion = motion;
    m_publishedMs = now();
}

void SimShaft::release(int token) {
    QMutexLocker lock(&m_mutex);
    if (token != m_driver) return;
    m_motion = {m_motion.positionAfter(double(now() - m_publishedMs) / 1000.0), 0.0, {}};
    m_publishedMs = now();
}

double SimShaft::position() const {
    QMutexLocker lock(&m_mutex);
    return m_motion.positionAfter(double(now() - m_publishedMs) / 1000.0);
}

double SimShaft::velocity() const {
    QMutexLocker lock(&m_mutex);
    const double seconds = double(now() - m_publishedMs) / 1000.0;
    if (endAhead(m_motion) && m_motion.positionAfter(seconds) == *m_motion.end) return 0.0;
    return m_motion.velocity;
}

SimShaftDriver::SimShaftDriver(std::shared_ptr<SimShaft> shaft)
    : m_shaft(std::move(shaft)), m_token(m_shaft->takeDrive()) {}

SimShaftDriver::~SimShaftDriver() {
    m_shaft->release(m_token);
}

void SimShaftDriver::publish(const SimShaftMotion& motion) {
    m_shaft->publish(m_token, motion);
}

std::shared_ptr<SimShaft> namedSimShaft(const QString& name) {
    static QMutex mutex;
    static QHash<QString, std::weak_ptr<SimShaft>> shafts;
    QMutexLocker lock(&mutex);
    std::shared_ptr<SimShaft> shaft = shafts.value(name).lock();
    if (!shaft) {
        shaft = std::make_shared<SimShaft>();
        shafts.insert(name, shaft);
    }
    return shaft;
}

Result<SimPortWithShaft> takeSimShaftKeys(const QString& port) {
    const qsizetype colon = port.indexOf(QLatin1Char(':'));
    if (colon < 0) return SimPortWithShaft{port, std::nullopt};
    QStringList kept;
    QString name;
    SimShaftSeat seat;
    for (const QString& item : port.mid(colon + 1).split(QLatin1Char(';'), Qt::SkipEmptyParts)) {
        const QString key = item.section(QLatin1Char('='), 0, 0).trimmed();
        const QString value = item.section(QLatin1Char('='), 1).trimmed();
        bool ok = false;
        if (key == QLatin1String("shaft")) {
            if (value.isEmpty())
                return badKey(port, QStringLiteral("shaft= needs a name, e.g. shaft=demo."));
            name = value;
        } else if (key == QLatin1String("shaftaxis")) {
            const int axis = value.toInt(&ok);
            if (!ok || axis < 1)
                return badKey(port,
                              QStringLiteral("shaftaxis=%1 is not an axis 1, 2, ...").arg(value));
            seat.axis = axis;
        } else if (key == QLatin1String("perturn")) {
            const double perTurn = value.toDouble(&ok);
            if (!ok || !(perTurn > 0.0) || !std::isfinite(perTurn))
                return badKey(port, QStringLiteral("perturn=%1 is not a number of shaft units "
                                                   "above 0.")
                                        .arg(value));
            seat.perTurn = perTurn;
        } else {
            kept << item;
        }
    }
    if (name.isEmpty() && (seat.axis || seat.perTurn))
        return badKey(port, QStringLiteral("shaftaxis= and perturn= need shaft=NAME."));
    SimPortWithShaft result;
    result.port = kept.isEmpty()
                      ? port.left(colon)
                      : port.left(colon) + QLatin1Char(':') + kept.join(QLatin1Char(';'));
    if (!name.isEmpty()) {
        seat.shaft = namedSimShaft(name);
        result.seat = seat;
    }
    return result;
}

Status driveShaft(const SimShaftPlug& plug, const std::shared_ptr<SimShaft>& shaft, int axis,
                  const QString& who) {
    if (!plug.drive)
        return Error::usage(
            QStringLiteral("%1 cannot drive a shaft: its simulator has no moving axis.").arg(who));
    const Status driven = plug.drive(shaft, axis);
    if (!driven) return Error::usage(QStringLiteral("%1: %2").arg(who, driven.error().message));
    return success();
}

Status followShaft(const SimShaftPlug& plug, const std::shared_ptr<SimShaft>& shaft, double perTurn,
                   const QString& who) {
    if (!plug.follow)
        return Error::usage(
            QStringLiteral("%1 cannot follow a shaft: its simulator has no position that "
                           "follows one.")
                .arg(who));
    const Status following = plug.follow(shaft, perTurn);
    if (!following)
        return Error::usage(QStringLiteral("%1: %2").arg(who, following.error().message));
    return success();
}

Status seatOnShaft(const SimShaftPlug& plug, const SimShaftSeat& seat, const QString& who) {
    if (plug.drive) {
        if (seat.perTurn)
            return Error::usage(
                QStringLiteral("%1 drives its shaft: perturn= belongs on the port of the device "
                               "that follows.")
                    .arg(who));
        return driveShaft(plug, seat.shaft, seat.axis.value_or(1), who);
    }
    if (seat.axis)
        return Error::usage(
            QStringLiteral("%1 follows its shaft: shaftaxis= belongs on the port of the device "
                           "that drives.")
                .arg(who));
    return followShaft(plug, seat.shaft, seat.perTurn.value_or(kSimShaftPerTurn), who);
}

}  // namespace cambench::comm
