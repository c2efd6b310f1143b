#include "ui/camcon/cameditor/cam_generator.h"

#include <cmath>

namespace cambench {

namespace {

qint32 wrapped(qint64 position, qint32 minPosition, qint64 span) {
    qint64 offset = (position - minPosition) % span;
    if (offset < 0) {
        offset += span;
    }
    return qint32(minPosition + offset);
}

}  // namespace

Result<QList<Cam>> CamGenerator::generate(const CamGeneratorSettings& settings, qint32 minPosition,
                                          qint32 maxPosition, bool rotary) {
    if (settings.start < minPosition || settings.start > maxPosition) {
        return Error::invalidData(tr("The start position %1 is outside the range %2..%3. "
                                     "Enter a start inside the range.")
                                      .arg(settings.start)
                                      .arg(minPosition)
                                      .arg(maxPosition));
    }
    const qint64 span = qint64(maxPosition) - minPosition + 1;
    // Rotary cams may run round to the start again; linear ones end at IMAX.
    const qint64 available = rotary ? span : qint64(maxPosition) - settings.start;

    double pitch = settings.pitch;
    qint64 length = settings.length;
    if (settings.mode == CamGeneratorSettings::Mode::CountAndDuty) {
        if (settings.count < 1 || settings.count > kMaxCamsPerTrack) {
            return Error::invalidData(
                tr("The number of cams must be between 1 and %1.").arg(kMaxCamsPerTrack));
        }
        if (settings.dutyPercent <= 0.0 || settings.dutyPercent >= 100.0) {
            return Error::invalidData(
                tr("The duty cycle must be above 0 % and below 100 %; "
                   "at 100 % the cams would touch."));
        }
        pitch = double(available) / settings.count;
        length = qint64(std::llround(pitch * settings.dutyPercent / 100.0));
        if (length < 1 || length >= qint64(std::floor(pitch))) {
            return Error::invalidData(tr("%1 cams with %2 % duty do not fit into %3 positions. "
                                         "Choose fewer cams or another duty cycle.")
                                          .arg(settings.count)
                                          .arg(settings.dutyPercent)
                                          .arg(available));
        }
    } else if (settings.length < 1 || settings.pitch <= settings.length) {
        return Error::invalidData(tr("The pitch (%1) must be larger than the cam length (%2), "
                                     "and the length at least 1; otherwise the cams overlap.")
                                      .arg(settings.pitch)
                                      .arg(settings.length));
    }

    QList<Cam> cams;
    for (int k = 0;; ++k) {
        const qint64 offset = qint64(std::llround(k * pitch));
        // Rotary: stop before the last cam would reach the first one again.
        if (rotary ? offset + length >= span : offset + length > available) {
            break;
        }
        // A tiny pitch on a huge axis would otherwise run away.
        if (cams.size() == kMaxCamsPerTrack) {
            return Error::invalidData(tr("These settings make more than %1 cams, the most a "
                                         "track holds. Choose a larger pitch.")
                                          .arg(kMaxCamsPerTrack));
        }
        const qint64 on = qint64(settings.start) + offset;
        cams.append({wrapped(on, minPosition, span), wrapped(on + length, minPosition, span)});
    }
    if (cams.isEmpty()) {
        return Error::invalidData(tr("No cam of length %1 fits between %2 and %3.")
                                      .arg(length)
                                      .arg(settings.start)
                                      .arg(maxPosition));
    }
    return cams;
}

}  // namespace cambench
