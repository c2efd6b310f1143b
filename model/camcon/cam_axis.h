#pragma once

#include "model/camcon/cam_program.h"

#include <QList>

namespace cambench {

// The actual-value axis as the editor sees it: IMIN..IMAX, rotary or linear.
// Positions are points; a cam covers [on, off) and, on a rotary axis with
// off < on, runs through IMAX back to IMIN.
struct Axis {
    qint32 min = 0;
    qint32 max = 359;
    bool rotary = true;

    qint64 span() const { return qint64(max) - min + 1; }
    qint32 wrap(qint64 position) const;
    qint32 clamp(qint64 position) const;
    // Rotary axes wrap a moved point round, linear axes stop at the ends.
    qint32 moved(qint32 position, qint64 delta) const;
    bool wraps(const Cam& cam) const { return rotary && cam.off < cam.on; }
    qint64 length(const Cam& cam) const;
    Cam withLength(const Cam& cam, qint64 length) const;
    // A whole cam shifted; on a linear axis the shift stops at the ends so
    // the length stays.
    Cam shifted(const Cam& cam, qint64 delta) const;
};

// A piece of a cam on the drawn axis, [from, to) in position units.
struct CamPiece {
    qint64 from = 0;
    qint64 to = 0;
};

// One piece, or two for a cam that wraps through zero.
QList<CamPiece> camPieces(const Cam& cam, const Axis& axis);

}  // namespace cambench
