#pragma once

#include "device_info.h"

#include <QList>
#include <QMap>
#include <QString>
#include <QStringList>

namespace cambench {

// Analogue cams (table interface, data areas 241..254): each analogue
// output follows a curve of base points, a value at each position.
constexpr int kAnalogueOutputs = 14;
constexpr int kMaxAnaloguePoints = 125;
// Provisional: the manual gives the analogue values no range; read as the
// signed 16 bits of the analogue output words ("scaled to 16 bits", area
// 204 offset "16 bit, signed"). The one place to change.
constexpr qint32 kMinAnalogueValue = -32768;
constexpr qint32 kMaxAnalogueValue = 32767;

struct AnaloguePoint {
    qint32 position = 0;  // actual-value units
    qint32 value = 0;     // the analogue value there
    friend bool operator==(const AnaloguePoint& a, const AnaloguePoint& b) {
        return a.position == b.position && a.value == b.value;
    }
};

// The base points of one analogue output, ordered by position.
struct AnalogueCamTrack {
    int output = 1;  // analogue output 1..14
    QList<AnaloguePoint> points;
    friend bool operator==(const AnalogueCamTrack& a, const AnalogueCamTrack& b) {
        return a.output == b.output && a.points == b.points;
    }
    friend bool operator!=(const AnalogueCamTrack& a, const AnalogueCamTrack& b) {
        return !(a == b);
    }
};

// Analogue output 1..14, at most 125 points, positions within the device's
// range and strictly ascending, values within the analogue range. One
// sentence per problem, naming output and point (counted from 1).
QStringList validateAnalogueCamTrack(const AnalogueCamTrack& track, const DeviceInfo& device);

}  // namespace cambench
