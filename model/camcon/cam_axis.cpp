#include "model/camcon/cam_axis.h"

#include <algorithm>

namespace cambench {

qint32 Axis::wrap(qint64 position) const {
    qint64 offset = (position - min) % span();
    if (offset < 0) {
        offset += span();
    }
    return qint32(min + offset);
}

qint32 Axis::clamp(qint64 position) const {
    return qint32(std::clamp<qint64>(position, min, max));
}

qint32 Axis::moved(qint32 position, qint64 delta) const {
    return rotary ? wrap(qint64(position) + delta) : clamp(qint64(position) + delta);
}

qint64 Axis::length(const Cam& cam) const {
    return wraps(cam) ? qint64(cam.off) - cam.on + span() : qint64(cam.off) - cam.on;
}

Cam Axis::withLength(const Cam& cam, qint64 length) const {
    return {cam.on, moved(cam.on, length)};
}

Cam Axis::shifted(const Cam& cam, qint64 delta) const {
    if (rotary) {
        return {wrap(qint64(cam.on) + delta), wrap(qint64(cam.off) + delta)};
    }
    const qint64 low = std::min(cam.on, cam.off);
    const qint64 high = std::max(cam.on, cam.off);
    delta = std::clamp<qint64>(delta, min - low, max - high);
    return {qint32(cam.on + delta), qint32(cam.off + delta)};
}

QList<CamPiece> camPieces(const Cam& cam, const Axis& axis) {
    if (axis.wraps(cam)) {
        return {{cam.on, qint64(axis.max) + 1}, {axis.min, cam.off}};
    }
    return {{std::min(cam.on, cam.off), std::max(cam.on, cam.off)}};
}

}  // namespace cambench
