#include "analogue_cams.h"

#include <QCoreApplication>

namespace cambench {

QStringList validateAnalogueCamTrack(const AnalogueCamTrack& track, const DeviceInfo& device) {
    QStringList problems;
    if (track.output < 1 || track.output > kAnalogueOutputs) {
        problems.append(QCoreApplication::translate("cambench::model",
                                                    "Analogue output %1 does not exist (1..%2).")
                            .arg(track.output)
                            .arg(kAnalogueOutputs));
        return problems;
    }
    if (track.points.size() > kMaxAnaloguePoints) {
        problems.append(
            QCoreApplication::translate("cambench::model",
                                        "Analogue output %1 has %2 base points; at most %3 fit.")
                .arg(track.output)
                .arg(track.points.size())
                .arg(kMaxAnaloguePoints));
    }
    for (qsizetype i = 0; i < track.points.size(); ++i) {
        const AnaloguePoint& point = track.points.at(i);
        const QString where =
            QCoreApplication::translate("cambench::model", "Analogue output %1, base point %2")
                .arg(track.output)
                .arg(i + 1);
        if (point.position < device.minPosition || point.position > device.maxPosition) {
            problems.append(
                QCoreApplication::translate("cambench::model", "%1: position %2 is outside %3..%4.")
                    .arg(where)
                    .arg(point.position)
                    .arg(device.minPosition)
                    .arg(device.maxPosition));
        }
        if (i > 0 && point.position <= track.points.at(i - 1).position) {
            problems.append(
                QCoreApplication::translate("cambench::model",
                                            "%1: position %2 does not come after the previous "
                                            "point's %3; order the points by position.")
                    .arg(where)
                    .arg(point.position)
                    .arg(track.points.at(i - 1).position));
        }
        if (point.value < kMinAnalogueValue || point.value > kMaxAnalogueValue) {
            problems.append(
                QCoreApplication::translate("cambench::model", "%1: value %2 is outside %3..%4.")
                    .arg(where)
                    .arg(point.value)
                    .arg(kMinAnalogueValue)
                    .arg(kMaxAnalogueValue));
        }
    }
    return problems;
}

}  // namespace cambench
