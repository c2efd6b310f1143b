#pragma once

#include "cam_axis.h"
#include "cam_program.h"
#include "dead_time_modes.h"
#include "dead_times.h"
#include "model/result.h"

#include <QList>
#include <QString>

#include <optional>

namespace cambench {

// Speeds are given as a person reads them: revolutions per minute ("1/min",
// one revolution = one cycle) on a rotary axis, positions per second
// ("pos/s") on a linear one. The arithmetic works in positions per second.
double toPositionsPerSecond(double speed, const Axis& axis);
double fromPositionsPerSecond(double positionsPerSecond, const Axis& axis);
QString speedUnit(const Axis& axis);

// One cam as it switches electrically at a speed: the output switches each
// edge early by speed × that edge's dead time, so that the actuator acts at
// the programmed position.
struct TimedCam {
    int number = 1;  // in the track, from 1
    Cam programmed;
    double on = 0;                     // electrical switch-on position (rotary: within the cycle)
    double off = 0;                    // electrical switch-off position
    double length = 0;                 // positions the output is on; <= 0: the cam vanishes
    std::optional<double> durationMs;  // how long the output is on; none at standstill
};

// What breaks the picture at a speed.
struct TimingProblem {
    enum class Kind {
        Vanishes,        // switch-off dead time longer than switch-on: the cam shrinks to nothing
        Merges,          // switch-on dead time longer: the cam reaches the next one
        ShortPulse,      // on for less than the minimum pulse of the output
        ShiftOverCycle,  // an edge moves by more than one cycle (rotary)
    };
    Kind kind = Kind::ShortPulse;
    int cam = 1;       // the cam (from 1)
    int nextCam = 0;   // Merges: the cam it reaches
    double fromSpeed;  // positions per second at and above which it happens
};

// Every cam of one output at one speed, the problems there, and the lowest
// speed at which the first problem happens.
struct OutputTiming {
    int output = 1;
    double onDeadTimeMs = 0;
    double offDeadTimeMs = 0;
    double shiftOn = 0;   // positions the switch-on edges move earlier
    double shiftOff = 0;  // the same for the switch-off edges
    QList<TimedCam> cams;
    QList<TimingProblem> problems;            // those that happen at this speed
    std::optional<TimingProblem> firstLimit;  // the lowest speed any problem starts at
    std::optional<double> shortestDurationMs;
};

// `deadTime` as the output's mode uses it; `positionsPerSecond` >= 0;
// `minPulseMs` 0 = no minimum. Path-time mode (provisional,
// docs/protocols/camcon-ascii.md names no formula): the switch-on edge moves by the switch-on dead
// time and the output stays on for the switching time, whatever the off point.
OutputTiming timeTrack(const Track& track, const OutputDeadTime& deadTime,
                       double positionsPerSecond, const Axis& axis, double minPulseMs = 0);

// Each output's dead time as timeTrack takes it: the modes where the device
// has them (table interface), else every plain dead time as mode Normal.
DeadTimeModes deadTimesAsModes(const DeadTimes& plain, const DeadTimeModes& modes);

// Every output of `program` that has cams, in output order; `minimumPulses`
// in 0.1 ms (an output not in it has none).
QList<OutputTiming> timeProgram(const CamProgram& program, const DeadTimeModes& deadTimes,
                                double positionsPerSecond, const Axis& axis,
                                const MinimumPulses& minimumPulses = {});

// The command line's minimum pulses: "12" (every output, ms), "3=12,4=8.5"
// (those outputs), or both ("5,3=12": output 3 12 ms, every other 5 ms).
// `outputs` is the highest output number. A decimal point, never a comma.
Result<MinimumPulses> parseMinimumPulses(const QString& text, int outputs);

// "output 4: cams 2 and 3 merge above 412 1/min".
QString describeProblem(int output, const TimingProblem& problem, const Axis& axis);

}  // namespace cambench
