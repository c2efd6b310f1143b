#pragma once

#include "model/result.h"

#include <QMutex>
#include <QString>

#include <functional>
#include <memory>
#include <optional>

namespace cambench::comm {

// How a simulated axis moves from a moment on, in its own units: at
// `position` then, `velocity` units per second (signed), and it stops at
// `end` when it has one (a target, an end limit). A follower extrapolates
// it, so a cam turns live between the requests its drive gets.
struct SimShaftMotion {
    double position = 0.0;
    double velocity = 0.0;
    std::optional<double> end;

    // Where the axis is `seconds` after this motion was published.
    double positionAfter(double seconds) const;
};

// The mechanical shaft of a simulated machine (issue 30): one simulated
// device with a moving axis drives it (publishes its actual position after
// every request it answers), devices that sit on it follow (a CamCon's
// position). Shared between threads: each device of the GUI's machine runs
// on its own worker.
class SimShaft {
public:
    using Clock = std::function<qint64()>;  // milliseconds, monotonic

    // `clock`: tests drive time themselves; default a steady clock.
    explicit SimShaft(Clock clock = {});

    // A drive takes the shaft; the one that took it last drives it (a
    // reconnected drive takes over from the one it replaces). The token
    // it gets is what it publishes with.
    int takeDrive();
    // The drive's motion now; ignored from a drive that no longer drives.
    void publish(int token, const SimShaftMotion& motion);
    // The drive goes away: the shaft stops where it is.
    void release(int token);

    // The driving axis's position now (0 before any drive published).
    double position() const;
    // Its velocity now, units per second (0 when it stands or reached its end).
    double velocity() const;

private:
    qint64 now() const;

    mutable QMutex m_mutex;
    Clock m_clock;
    SimShaftMotion m_motion;
    qint64 m_publishedMs = 0;
    int m_driver = 0;
};

// A drive's hold on its shaft, kept by the simulated device that drives
// it: it publishes the drive's motion; when the drive goes, the shaft
// stops where it is.
class SimShaftDriver {
public:
    explicit SimShaftDriver(std::shared_ptr<SimShaft> shaft);
    ~SimShaftDriver();
    SimShaftDriver(const SimShaftDriver&) = delete;
    SimShaftDriver& operator=(const SimShaftDriver&) = delete;

    void publish(const SimShaftMotion& motion);

private:
    std::shared_ptr<SimShaft> m_shaft;
    int m_token;
};

// The named shafts of this process, for the in-process "sim:shaft=NAME"
// ports: every port naming the same shaft is on one. A shaft lives while a
// device is on it.
std::shared_ptr<SimShaft> namedSimShaft(const QString& name);

// What a simulated device can do on a shaft, given by its family's
// simulator with its SimulatedLine (empty: it cannot).
struct SimShaftPlug {
    // Its axis `axis` (1-based) drives `shaft`; a Usage error when it has
    // no such axis.
    std::function<Status(const std::shared_ptr<SimShaft>& shaft, int axis)> drive;
    // Its position follows `shaft`: `perTurn` shaft units make one turn of
    // its position range.
    std::function<Status(const std::shared_ptr<SimShaft>& shaft, double perTurn)> follow;
};

// Where a simulated device sits on a shaft: the port keys shaft=NAME,
// shaftaxis=N (the driving axis, default 1) and perturn=U (a follower's
// shaft units per turn, default kSimShaftPerTurn).
struct SimShaftSeat {
    std::shared_ptr<SimShaft> shaft;
    std::optional<int> axis;
    std::optional<double> perTurn;
};

// Drive units per turn of a follower unless the machine says otherwise:
// a drive counting in degrees turns the CamCon's default 0..359 one to one.
inline constexpr double kSimShaftPerTurn = 360.0;

// Takes the shaft keys out of a "sim:..." port: `port` without them (what
// the family's simulator reads) and the seat they name, if any. A Usage
// error names a bad value.
struct SimPortWithShaft {
    QString port;
    std::optional<SimShaftSeat> seat;
};
Result<SimPortWithShaft> takeSimShaftKeys(const QString& port);

// The machine's shaft (cambench-sim --machine): `who` names the device in
// an error (one that cannot drive or follow, an axis it lacks).
Status driveShaft(const SimShaftPlug& plug, const std::shared_ptr<SimShaft>& shaft, int axis,
                  const QString& who);
Status followShaft(const SimShaftPlug& plug, const std::shared_ptr<SimShaft>& shaft, double perTurn,
                   const QString& who);

// A "sim:shaft=..." port's seat: a device that can drive drives, else one
// that can follow follows (shaftaxis= is a drive's key, perturn= a
// follower's).
Status seatOnShaft(const SimShaftPlug& plug, const SimShaftSeat& seat, const QString& who);

}  // namespace cambench::comm
