#pragma once

#include "cam_program.h"
#include "device_info.h"

#include <QList>
#include <QString>

namespace cambench {

// Current devices hold up to 125 cams per track (notes 3, table interface).
constexpr int kMaxCamsPerTrack = 125;

// One thing wrong with a cam program. `output` is 1-based, -1 when the
// problem concerns the whole program; `cam` is the 0-based index into
// Track::cams, -1 when it concerns the whole track. The message counts cams
// from 1, as a person does: "program 3, output 5, cam 2: ...".
struct CamProblem {
    int program = 0;
    int output = -1;
    int cam = -1;
    QString message;
};

// A cam covers the half-open range [on, off): the output switches on at
// `on` and is off again at `off`. With off < on the cam wraps through zero
// (rotary axes only). Hence [300,20] and [20,40] touch but do not overlap.
bool camCovers(const Cam& cam, qint32 position);
// Whether the track's output is on at `position`.
bool trackActiveAt(const Track& track, qint32 position);
// Whether two cams cover a common position (wrapping cams included): a
// device refuses to hold both on one track.
bool camsOverlap(const Cam& a, const Cam& b);

// Checks a track of program `program` against the device: both points in
// minPosition..maxPosition, on != off, off < on only on a rotary axis, no
// overlap (wrap-around included), at most kMaxCamsPerTrack cams, output in
// 1..outputs.
QList<CamProblem> validateTrack(const Track& track, int program, const DeviceInfo& device,
                                bool rotary);
// The program number (0..programs-1), every track, and that each track is
// stored under its own output number.
QList<CamProblem> validateProgram(const CamProgram& program, const DeviceInfo& device, bool rotary);

// Orders the cams by switch-on point (stable, so equal points keep their order).
void normaliseTrack(Track& track);
// Normalises every track and drops tracks without cams (an absent output
// is an empty track), so equal programs compare equal.
void normaliseProgram(CamProgram& program);

}  // namespace cambench
