#pragma once

#include <QList>
#include <QMap>
#include <QString>

namespace cambench {

// One cam: the output switches on at `on` and off at `off` (actual-value
// units). On a rotary axis off < on means the cam wraps through zero.
struct Cam {
    qint32 on = 0;
    qint32 off = 0;
    friend bool operator==(const Cam& a, const Cam& b) { return a.on == b.on && a.off == b.off; }
    friend bool operator!=(const Cam& a, const Cam& b) { return !(a == b); }
};

// The cams of one output in one program, ordered by switch-on point.
// `output` counts from 1, as on the device's own settings; the 0-based
// numbers of the ASCII protocol never leave comm/.
struct Track {
    int output = 1;
    QList<Cam> cams;
    friend bool operator==(const Track& a, const Track& b) {
        return a.output == b.output && a.cams == b.cams;
    }
    friend bool operator!=(const Track& a, const Track& b) { return !(a == b); }
};

// A cam program: program numbers count from 0, as on the device.
// Only tracks that hold at least one cam need to be present; an absent
// output is an empty track.
struct CamProgram {
    int number = 0;
    QString name;
    QMap<int, Track> tracks;  // key = output (1-based)

    friend bool operator==(const CamProgram& a, const CamProgram& b) {
        return a.number == b.number && a.name == b.name && a.tracks == b.tracks;
    }
    friend bool operator!=(const CamProgram& a, const CamProgram& b) { return !(a == b); }
};

}  // namespace cambench
