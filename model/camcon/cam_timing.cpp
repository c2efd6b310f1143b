#include "cam_timing.h"

#include <algorithm>
#include <cmath>

namespace cambench {

namespace {

constexpr double kSecondsPerMinute = 60.0;
constexpr double kMsPerSecond = 1000.0;

// Dead times of the two edges in ms (device units: 0.1 ms).
struct Edges {
    double onMs = 0;
    double offMs = 0;
    std::optional<double> switchingMs;  // path-time mode: on for this long
};

Edges edgesOf(const OutputDeadTime& deadTime) {
    switch (deadTime.mode) {
        case DeadTimeMode::Normal:
            return {deadTime.normal / 10.0, deadTime.normal / 10.0, std::nullopt};
        case DeadTimeMode::SeparateOnOff:
            return {deadTime.on / 10.0, deadTime.off / 10.0, std::nullopt};
        case DeadTimeMode::PathTime:
            return {deadTime.on / 10.0, deadTime.on / 10.0, deadTime.off / 10.0};
    }
    return {};
}

// The programmed length of a cam in positions; a rotary cam with off < on
// wraps through the cycle's end.
double lengthOf(const Cam& cam, const Axis& axis) {
    const double length = double(cam.off) - cam.on;
    return (axis.rotary && length < 0) ? length + double(axis.span()) : length;
}

double distance(double from, double to, const Axis& axis) {
    const double d = to - from;
    return (axis.rotary && d < 0) ? d + double(axis.span()) : d;
}

double wrapped(double position, const Axis& axis) {
    if (!axis.rotary) return position;
    const double cycle = double(axis.span());
    double offset = std::fmod(position - axis.min, cycle);
    if (offset < 0) offset += cycle;
    return axis.min + offset;
}

QString speedText(double positionsPerSecond, const Axis& axis) {
    const double speed = fromPositionsPerSecond(positionsPerSecond, axis);
    return QStringLiteral("%1 %2").arg(QString::number(speed, 'f', speed >= 100 ? 0 : 1),
                                       speedUnit(axis));
}

}  // namespace

double toPositionsPerSecond(double speed, const Axis& axis) {
    return axis.rotary ? speed * double(axis.span()) / kSecondsPerMinute : speed;
}

double fromPositionsPerSecond(double positionsPerSecond, const Axis& axis) {
    return axis.rotary ? positionsPerSecond * kSecondsPerMinute / double(axis.span())
                       : positionsPerSecond;
}

QString speedUnit(const Axis& axis) {
    return axis.rotary ? QStringLiteral("1/min") : QStringLiteral("pos/s");
}

OutputTiming timeTrack(const Track& track, const OutputDeadTime& deadTime,
                       double positionsPerSecond, const Axis& axis, double minPulseMs) {
    const double v = std::max(0.0, positionsPerSecond);
    const Edges edges = edgesOf(deadTime);
    OutputTiming timing;
    timing.output = track.output;
    timing.onDeadTimeMs = edges.onMs;
    timing.offDeadTimeMs = edges.switchingMs ? edges.onMs : edges.offMs;
    timing.shiftOn = v * edges.onMs / kMsPerSecond;
    timing.shiftOff = edges.switchingMs ? timing.shiftOn : v * edges.offMs / kMsPerSecond;

    QList<TimingProblem> limits;
    const qsizetype count = track.cams.size();
    for (qsizetype i = 0; i < count; ++i) {
        const Cam& cam = track.cams.at(i);
        const double length = lengthOf(cam, axis);
        TimedCam timed;
        timed.number = int(i) + 1;
        timed.programmed = cam;
        const double on = cam.on - timing.shiftOn;
        if (edges.switchingMs) {
            timed.length = v * *edges.switchingMs / kMsPerSecond;
            timed.durationMs = *edges.switchingMs;
        } else {
            timed.length = length - (timing.shiftOff - timing.shiftOn);
            if (v > 0) timed.durationMs = std::max(0.0, timed.length) * kMsPerSecond / v;
        }
        timed.on = wrapped(on, axis);
        timed.off = wrapped(on + std::max(0.0, timed.length), axis);
        timing.cams << timed;

        const auto limit = [&](TimingProblem::Kind kind, double from, int next = 0) {
            limits << TimingProblem{kind, timed.number, next, std::max(0.0, from)};
        };
        const double stretchMs = edges.offMs - edges.onMs;  // how much longer the off edge waits
        if (!edges.switchingMs && stretchMs > 0)
            limit(TimingProblem::Kind::Vanishes, length * kMsPerSecond / stretchMs);
        // The gap to the next cam closes when the on edges lead the off edges.
        const bool hasNext = axis.rotary ? count > 1 : i + 1 < count;
        if (hasNext) {
            const Cam& next = track.cams.at((i + 1) % count);
            if (edges.switchingMs && *edges.switchingMs > 0) {
                limit(TimingProblem::Kind::Merges,
                      distance(cam.on, next.on, axis) * kMsPerSecond / *edges.switchingMs,
                      int((i + 1) % count) + 1);
            } else if (!edges.switchingMs && stretchMs < 0) {
                limit(TimingProblem::Kind::Merges,
                      distance(cam.off, next.on, axis) * kMsPerSecond / -stretchMs,
                      int((i + 1) % count) + 1);
            }
        }
        if (minPulseMs > 0) {
            if (edges.switchingMs) {
                if (*edges.switchingMs < minPulseMs) limit(TimingProblem::Kind::ShortPulse, 0);
            } else if (minPulseMs + stretchMs > 0) {
                // on for length / v - stretch: shorter than the pulse above this speed
                limit(TimingProblem::Kind::ShortPulse,
                      length * kMsPerSecond / (minPulseMs + stretchMs));
            }
        }
    }
    const double longestMs = std::max(edges.onMs, timing.offDeadTimeMs);
    if (axis.rotary && longestMs > 0 && count > 0)
        limits << TimingProblem{TimingProblem::Kind::ShiftOverCycle, 1, 0,
                                double(axis.span()) * kMsPerSecond / longestMs};

    for (const TimingProblem& problem : limits) {
        if (problem.fromSpeed <= v && (v > 0 || problem.fromSpeed == 0)) timing.problems << problem;
        if (!timing.firstLimit || problem.fromSpeed < timing.firstLimit->fromSpeed)
            timing.firstLimit = problem;
    }
    for (const TimedCam& cam : timing.cams) {
        if (cam.durationMs &&
            (!timing.shortestDurationMs || *cam.durationMs < *timing.shortestDurationMs))
            timing.shortestDurationMs = cam.durationMs;
    }
    return timing;
}

DeadTimeModes deadTimesAsModes(const DeadTimes& plain, const DeadTimeModes& modes) {
    if (!modes.isEmpty()) return modes;
    DeadTimeModes result;
    for (auto it = plain.cbegin(); it != plain.cend(); ++it)
        result.insert(it.key(), {DeadTimeMode::Normal, it.value(), 0, 0});
    return result;
}

QList<OutputTiming> timeProgram(const CamProgram& program, const DeadTimeModes& deadTimes,
                                double positionsPerSecond, const Axis& axis,
                                const MinimumPulses& minimumPulses) {
    QList<OutputTiming> outputs;
    for (const Track& track : program.tracks) {
        if (track.cams.isEmpty()) continue;
        outputs << timeTrack(track, deadTimes.value(track.output), positionsPerSecond, axis,
                             minimumPulses.value(track.output) / 10.0);
    }
    return outputs;
}

Result<MinimumPulses> parseMinimumPulses(const QString& text, int outputs) {
    const auto tenths = [](const QString& ms) -> std::optional<qint32> {
        bool ok = false;
        const double value = ms.trimmed().toDouble(&ok);  // C locale: "8.5", never "8,5"
        if (!ok || value < 0 || value > 1e6) return std::nullopt;
        return qint32(std::lround(value * 10));
    };
    MinimumPulses pulses;
    std::optional<qint32> everyOutput;
    for (const QString& part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const qsizetype equals = part.indexOf(QLatin1Char('='));
        if (equals < 0) {
            // "2=7,5" is a German 7.5, not "every other output 5 ms": the
            // value for every output comes first or not at all.
            if (!pulses.isEmpty())
                return Error::usage(
                    QStringLiteral("\"%1\" after an output's value: give the value for every "
                                   "output first (\"5,2=7.5\"), and milliseconds with a decimal "
                                   "point")
                        .arg(part.trimmed()));
            everyOutput = tenths(part);
            if (!everyOutput)
                return Error::usage(
                    QStringLiteral("minimum pulse \"%1\" is not milliseconds (0 or more, with "
                                   "a decimal point)")
                        .arg(part.trimmed()));
            continue;
        }
        bool ok = false;
        const int output = part.left(equals).trimmed().toInt(&ok);
        if (!ok || output < 1 || output > outputs)
            return Error::usage(QStringLiteral("\"%1\": the output must be 1 to %2")
                                    .arg(part.trimmed())
                                    .arg(outputs));
        const std::optional<qint32> value = tenths(part.mid(equals + 1));
        if (!value)
            return Error::usage(
                QStringLiteral("\"%1\": the minimum pulse must be milliseconds (0 or more)")
                    .arg(part.trimmed()));
        pulses.insert(output, *value);
    }
    if (everyOutput) {
        for (int output = 1; output <= outputs; ++output)
            if (!pulses.contains(output)) pulses.insert(output, *everyOutput);
    }
    return pulses;
}

QString describeProblem(int output, const TimingProblem& problem, const Axis& axis) {
    const QString where = problem.fromSpeed > 0
                              ? QStringLiteral("above %1").arg(speedText(problem.fromSpeed, axis))
                              : QStringLiteral("at every speed");
    switch (problem.kind) {
        case TimingProblem::Kind::Vanishes:
            return QStringLiteral("output %1: cam %2 vanishes %3")
                .arg(output)
                .arg(problem.cam)
                .arg(where);
        case TimingProblem::Kind::Merges:
            return QStringLiteral("output %1: cams %2 and %3 merge %4")
                .arg(output)
                .arg(problem.cam)
                .arg(problem.nextCam)
                .arg(where);
        case TimingProblem::Kind::ShortPulse:
            return QStringLiteral("output %1: cam %2 is on for less than the minimum pulse %3")
                .arg(output)
                .arg(problem.cam)
                .arg(where);
        case TimingProblem::Kind::ShiftOverCycle:
            return QStringLiteral("output %1: the switch points move by more than one cycle %2")
                .arg(output)
                .arg(where);
    }
    return {};
}

}  // namespace cambench
