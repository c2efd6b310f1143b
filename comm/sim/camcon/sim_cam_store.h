#pragma once

#include "model/camcon/cam_program.h"

#include <QList>
#include <QMap>

namespace cambench::comm {

// Device error numbers the simulator answers with (manual 4.6.1).
namespace sim_errors {
constexpr qint32 kUnknown = -1;  // invalid value, overlap, no such item
constexpr qint32 kRamTooSmall = -10;
constexpr qint32 kDeadTimeTooLarge = -12;
constexpr qint32 kEepromFull = -21;
constexpr qint32 kBlockZeroLength = -41;
constexpr qint32 kEraseFailed = -42;
constexpr qint32 kBlockOrder = -43;
constexpr qint32 kStartFailed = -44;
constexpr qint32 kBlockLength = -45;
constexpr qint32 kIncomplete = -46;
}  // namespace sim_errors

// The cams of every program, by 0-based protocol output numbers, with the
// checks a device makes before it stores a cam: range, no overlap on the
// track, capacity. Empty tracks and programs are not kept, so that two
// stores with the same cams compare equal.
class SimCamStore {
public:
    using Tracks = QMap<int, QList<Cam>>;  // output (0-based) -> cams by on-point

    SimCamStore() = default;
    SimCamStore(qint32 minPosition, qint32 maxPosition, qint32 capacity);

    // 0 on success, else a device error number.
    qint32 insert(int program, int output, Cam cam);
    qint32 remove(int program, int output, qint32 on);
    qint32 change(int program, int output, qint32 oldOn, Cam cam);
    // Replaces the whole track (table interface); nothing changes on an error.
    qint32 replaceTrack(int program, int output, const QList<Cam>& cams);
    void removeProgram(int program);
    void copyProgram(int from, int to);
    void copyTrack(int program, int fromOutput, int toOutput);
    void clear() { m_programs.clear(); }

    QList<Cam> track(int program, int output) const;
    const QMap<int, Tracks>& programs() const { return m_programs; }
    qint32 camCount() const;

    // Whether any cam of the track covers `position`.
    bool isOn(int program, int output, qint32 position) const;

    // [on, off) with off < on wrapping through the end of the axis.
    bool validCam(const Cam& cam) const;
    bool overlaps(const Cam& a, const Cam& b) const;

    friend bool operator==(const SimCamStore& a, const SimCamStore& b) {
        return a.m_programs == b.m_programs;
    }

private:
    void setTrack(int program, int output, QList<Cam> cams);
    qint32 checkFits(const QList<Cam>& others, const Cam& cam) const;

    qint32 m_min = 0;
    qint32 m_max = 359;
    qint32 m_capacity = 8000;
    QMap<int, Tracks> m_programs;
};

// The device's search cursor of ?NF/?NL/?NN/?NP/?NS (notes 3). It points
// into the track selected by the last ?NF; -1 is before the first cam,
// count() after the last.
class SimCamCursor {
public:
    struct Answer {
        bool found = false;  // false: both points are 0x80000000
        Cam cam;
        bool earlier = false;
        bool more = false;
    };

    bool hasTrack() const { return m_program >= 0; }
    Answer first(const SimCamStore& store, int program, int output);
    Answer last(const SimCamStore& store);
    Answer next(const SimCamStore& store);
    Answer previous(const SimCamStore& store);
    Answer search(const SimCamStore& store, qint32 fromOn);
    void reset() { *this = SimCamCursor(); }

private:
    Answer at(const QList<Cam>& cams, int index);

    int m_program = -1;
    int m_output = -1;
    int m_index = -1;
};

}  // namespace cambench::comm
