#include "cam_validation.h"

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

namespace cambench {

namespace {

QString where(int program, int output, int cam) {
    QString text = QStringLiteral("program %1").arg(program);
    if (output >= 0) text += QStringLiteral(", output %1").arg(output);
    if (cam >= 0) text += QStringLiteral(", cam %1").arg(cam + 1);
    return text;
}

CamProblem problem(int program, int output, int cam, const QString& what) {
    return {program, output, cam, where(program, output, cam) + QStringLiteral(": ") + what};
}

// A piece of the axis a cam covers, [start, end); a wrapping cam has two.
struct Span {
    qint64 start;
    qint64 end;
    int cam;
};

QString camText(const Cam& cam) {
    return QStringLiteral("%1..%2").arg(cam.on).arg(cam.off);
}

// Problems of one cam on its own; empty if the cam can take part in the
// overlap check.
QList<CamProblem> camProblems(const Cam& cam, int index, int program, int output,
                              const DeviceInfo& device, bool rotary) {
    QList<CamProblem> problems;
    const auto checkPoint = [&](qint32 point, const char* name) {
        if (point < device.minPosition) {
            problems << problem(program, output, index,
                                QStringLiteral("%1 %2 is below the minimum %3")
                                    .arg(QLatin1String(name))
                                    .arg(point)
                                    .arg(device.minPosition));
        } else if (point > device.maxPosition) {
            problems << problem(program, output, index,
                                QStringLiteral("%1 %2 is above the maximum %3")
                                    .arg(QLatin1String(name))
                                    .arg(point)
                                    .arg(device.maxPosition));
        }
    };
    checkPoint(cam.on, "switch-on point");
    checkPoint(cam.off, "switch-off point");
    if (cam.on == cam.off) {
        problems << problem(program, output, index,
                            QStringLiteral("switch-on and switch-off point are both %1, so the "
                                           "cam would never switch")
                                .arg(cam.on));
    } else if (cam.off < cam.on && !rotary) {
        problems << problem(program, output, index,
                            QStringLiteral("switch-off point %1 is below the switch-on point %2; "
                                           "only on a rotary axis may a cam wrap through zero")
                                .arg(cam.off)
                                .arg(cam.on));
    }
    return problems;
}

}  // namespace

bool camCovers(const Cam& cam, qint32 position) {
    if (cam.on <= cam.off) return position >= cam.on && position < cam.off;
    return position >= cam.on || position < cam.off;
}

bool trackActiveAt(const Track& track, qint32 position) {
    return std::any_of(track.cams.cbegin(), track.cams.cend(),
                       [position](const Cam& cam) { return camCovers(cam, position); });
}

bool camsOverlap(const Cam& a, const Cam& b) {
    // A wrapping cam covers [on, end of axis] and [start of axis, off): as
    // spans without ends that is [on, +inf) and (-inf, off), which meet
    // another cam's positions exactly where the axis-bound spans would.
    const auto spans = [](const Cam& cam) {
        constexpr qint64 kLow = std::numeric_limits<qint64>::min();
        constexpr qint64 kHigh = std::numeric_limits<qint64>::max();
        std::vector<std::pair<qint64, qint64>> result;
        if (cam.on < cam.off) {
            result.emplace_back(cam.on, cam.off);
        } else if (cam.off < cam.on) {
            result.emplace_back(cam.on, kHigh);
            result.emplace_back(kLow, cam.off);
        }
        return result;
    };
    for (const auto& x : spans(a)) {
        for (const auto& y : spans(b)) {
            if (x.first < y.second && y.first < x.second) return true;
        }
    }
    return false;
}

QList<CamProblem> validateTrack(const Track& track, int program, const DeviceInfo& device,
                                bool rotary) {
    QList<CamProblem> problems;
    if (track.output < 1 || track.output > device.outputs) {
        problems << problem(program, track.output, -1,
                            QStringLiteral("the device has outputs 1..%1").arg(device.outputs));
    }
    if (track.cams.size() > kMaxCamsPerTrack) {
        problems << problem(program, track.output, -1,
                            QStringLiteral("%1 cams, but a track holds at most %2")
                                .arg(track.cams.size())
                                .arg(kMaxCamsPerTrack));
    }

    // Sweep over the covered spans sorted by start: a span that starts
    // before the furthest end seen so far overlaps the cam owning that end.
    // O(n log n), so even a damaged file with huge tracks is checked quickly.
    const qint64 axisEnd = qint64(device.maxPosition) + 1;
    std::vector<Span> spans;
    for (int i = 0; i < track.cams.size(); ++i) {
        const Cam& cam = track.cams.at(i);
        const QList<CamProblem> own = camProblems(cam, i, program, track.output, device, rotary);
        problems << own;
        if (!own.isEmpty()) continue;
        if (cam.on < cam.off) {
            spans.push_back({cam.on, cam.off, i});
        } else {
            spans.push_back({cam.on, axisEnd, i});
            spans.push_back({device.minPosition, cam.off, i});
        }
    }
    std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) {
        return a.start != b.start ? a.start < b.start : a.cam < b.cam;
    });
    std::vector<bool> reported(std::size_t(track.cams.size()), false);
    const Span* furthest = nullptr;
    for (const Span& span : spans) {
        if (span.start >= span.end) continue;
        if (furthest && span.start < furthest->end && furthest->cam != span.cam &&
            !reported[std::size_t(span.cam)]) {
            reported[std::size_t(span.cam)] = true;
            problems << problem(program, track.output, span.cam,
                                QStringLiteral("%1 overlaps cam %2 (%3)")
                                    .arg(camText(track.cams.at(span.cam)))
                                    .arg(furthest->cam + 1)
                                    .arg(camText(track.cams.at(furthest->cam))));
        }
        if (!furthest || span.end > furthest->end) furthest = &span;
    }
    return problems;
}

QList<CamProblem> validateProgram(const CamProgram& program, const DeviceInfo& device,
                                  bool rotary) {
    QList<CamProblem> problems;
    if (program.number < 0 || program.number >= device.programs) {
        problems << problem(
            program.number, -1, -1,
            QStringLiteral("the device has programs 0..%1").arg(device.programs - 1));
    }
    for (auto it = program.tracks.cbegin(); it != program.tracks.cend(); ++it) {
        if (it.key() != it->output) {
            problems << problem(program.number, it.key(), -1,
                                QStringLiteral("the track stored for output %1 says it is "
                                               "output %2")
                                    .arg(it.key())
                                    .arg(it->output));
        }
        problems << validateTrack(*it, program.number, device, rotary);
    }
    return problems;
}

void normaliseTrack(Track& track) {
    std::stable_sort(track.cams.begin(), track.cams.end(),
                     [](const Cam& a, const Cam& b) { return a.on < b.on; });
}

void normaliseProgram(CamProgram& program) {
    for (auto it = program.tracks.begin(); it != program.tracks.end();) {
        if (it->cams.isEmpty()) {
            it = program.tracks.erase(it);
        } else {
            normaliseTrack(*it);
            ++it;
        }
    }
}

}  // namespace cambench
