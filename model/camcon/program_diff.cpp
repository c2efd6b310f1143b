#include "program_diff.h"

#include <QSet>

#include <algorithm>

namespace cambench {

namespace {

// The cycle both programs fit in: a wrapping cam runs from `on` to its end.
// Only overlaps matter here, so any length above every position will do.
qint64 cycleOf(const CamProgram& a, const CamProgram& b) {
    qint64 highest = 0;
    for (const CamProgram* program : {&a, &b})
        for (const Track& track : program->tracks)
            for (const Cam& cam : track.cams)
                highest = std::max<qint64>({highest, cam.on, cam.off});
    return highest + 1;
}

// The cam as one or two half-open stretches [from, to) of the cycle.
QList<QPair<qint64, qint64>> stretches(const Cam& cam, qint64 cycle) {
    if (cam.on <= cam.off) return {{cam.on, cam.off}};
    return {{cam.on, cycle}, {0, cam.off}};
}

// How much of the cycle both cams cover; an empty cam (on == off) counts
// as one position, so that a moved zero-length cam still pairs.
qint64 overlap(const Cam& x, const Cam& y, qint64 cycle) {
    const auto widen = [](Cam cam) {
        if (cam.on == cam.off) cam.off = cam.on + 1;
        return cam;
    };
    qint64 shared = 0;
    for (const auto& [x0, x1] : stretches(widen(x), cycle + 1))
        for (const auto& [y0, y1] : stretches(widen(y), cycle + 1))
            shared += std::max<qint64>(0, std::min(x1, y1) - std::max(x0, y0));
    return shared;
}

void diffTrack(int output, const QList<Cam>& a, const QList<Cam>& b, qint64 cycle,
               QList<CamDifference>& out) {
    QSet<int> pairedA;
    QSet<int> pairedB;
    // Equal cams are unchanged, whatever their number in the track.
    for (int i = 0; i < a.size(); ++i) {
        for (int j = 0; j < b.size(); ++j) {
            if (pairedB.contains(j) || a.at(i) != b.at(j)) continue;
            pairedA.insert(i);
            pairedB.insert(j);
            break;
        }
    }
    QList<CamDifference> found;
    for (int i = 0; i < a.size(); ++i) {
        if (pairedA.contains(i)) continue;
        int best = -1;
        qint64 bestOverlap = 0;
        for (int j = 0; j < b.size(); ++j) {
            if (pairedB.contains(j)) continue;
            const qint64 shared = overlap(a.at(i), b.at(j), cycle);
            if (shared > bestOverlap) {
                best = j;
                bestOverlap = shared;
            }
        }
        CamDifference difference;
        difference.output = output;
        difference.camA = i + 1;
        difference.a = a.at(i);
        if (best >= 0) {
            pairedB.insert(best);
            difference.kind = CamDifference::Kind::Changed;
            difference.camB = best + 1;
            difference.b = b.at(best);
        } else {
            difference.kind = CamDifference::Kind::OnlyInA;
        }
        found << difference;
    }
    for (int j = 0; j < b.size(); ++j) {
        if (pairedB.contains(j)) continue;
        CamDifference difference;
        difference.kind = CamDifference::Kind::OnlyInB;
        difference.output = output;
        difference.camB = j + 1;
        difference.b = b.at(j);
        found << difference;
    }
    // In the order of the cycle: by where the cam starts (A's, else B's).
    std::stable_sort(found.begin(), found.end(),
                     [](const CamDifference& x, const CamDifference& y) {
                         const qint32 xs = x.camA > 0 ? x.a.on : x.b.on;
                         const qint32 ys = y.camA > 0 ? y.a.on : y.b.on;
                         return xs < ys;
                     });
    out << found;
}

QString range(const Cam& cam) {
    return QStringLiteral("%1..%2").arg(cam.on).arg(cam.off);
}

}  // namespace

ProgramDiff diffPrograms(const CamProgram& a, const CamProgram& b) {
    ProgramDiff diff;
    diff.nameA = a.name;
    diff.nameB = b.name;
    const qint64 cycle = cycleOf(a, b);
    QList<int> outputs = a.tracks.keys() + b.tracks.keys();
    std::sort(outputs.begin(), outputs.end());
    outputs.erase(std::unique(outputs.begin(), outputs.end()), outputs.end());
    for (int output : outputs)
        diffTrack(output, a.tracks.value(output).cams, b.tracks.value(output).cams, cycle,
                  diff.cams);
    return diff;
}

AppliedDifferences applyDifferences(const CamProgram& target, DiffSide side,
                                    const QList<CamDifference>& selected) {
    AppliedDifferences applied;
    QSet<int> failed;
    const bool onA = side == DiffSide::A;
    for (const CamDifference& difference : selected) {
        const int output = difference.output;
        if (failed.contains(output)) continue;
        if (!applied.tracks.contains(output)) {
            Track track = target.tracks.value(output);
            track.output = output;
            applied.tracks.insert(output, track);
        }
        QList<Cam>& cams = applied.tracks[output].cams;
        const bool mine = onA ? difference.camA > 0 : difference.camB > 0;
        const bool theirs = onA ? difference.camB > 0 : difference.camA > 0;
        const Cam& own = onA ? difference.a : difference.b;
        const Cam& other = onA ? difference.b : difference.a;
        if (mine) {
            const qsizetype at = cams.indexOf(own);
            if (at < 0) {
                failed.insert(output);
                applied.tracks.remove(output);
                applied.problems << QStringLiteral("output %1: cam %2..%3 is no longer there")
                                        .arg(output)
                                        .arg(own.on)
                                        .arg(own.off);
                continue;
            }
            cams.removeAt(at);
        }
        if (theirs) cams.append(other);
    }
    for (Track& track : applied.tracks)
        std::sort(track.cams.begin(), track.cams.end(),
                  [](const Cam& x, const Cam& y) { return x.on < y.on; });
    return applied;
}

QString describeDifference(const CamDifference& difference) {
    switch (difference.kind) {
        case CamDifference::Kind::Changed:
            return QStringLiteral("output %1, cam %2: %3 → %4")
                .arg(difference.output)
                .arg(difference.camA == difference.camB
                         ? QString::number(difference.camA)
                         : QStringLiteral("%1 (in B %2)").arg(difference.camA).arg(difference.camB))
                .arg(range(difference.a), range(difference.b));
        case CamDifference::Kind::OnlyInA:
            return QStringLiteral("output %1: cam %2 only in A")
                .arg(difference.output)
                .arg(range(difference.a));
        case CamDifference::Kind::OnlyInB:
            return QStringLiteral("output %1: cam %2 only in B")
                .arg(difference.output)
                .arg(range(difference.b));
    }
    return {};
}

}  // namespace cambench
