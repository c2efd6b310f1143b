#pragma once

#include "model/camcon/cam_program.h"
#include "model/result.h"

#include <QList>

namespace cambench::comm::table {

// The cam rules of the table interface (manual 3.1, areas 1..200): a track
// is words 1..250 of its area, cam n's switch-on point at word 2n-1 and its
// switch-off point at word 2n.
// - An empty cam reads 0x80000000 for both points; writing a cam into an
//   empty place creates it.
// - Writing a cam with equal points deletes the cam at that place.
// - Writing at least 2 cams (16 bytes) from cam 1 replaces the whole track:
//   every cam there before is gone. Writing a single cam (8 bytes) at cam 1
//   changes only cam 1.
// - On and off points always travel together (at least 8 bytes).

inline constexpr qint32 kEmptyCamWord = qint32(0x80000000u);
inline constexpr int kMaxTrackCams = 125;
inline constexpr int kFirstCamWord = 1;

// Provisional: a whole-track rewrite needs at least 2 cams, so a track of 0
// or 1 cams is padded with empty cams (0x80000000 pairs), on the reading
// that writing back what an empty place reads leaves the place empty.
inline constexpr qint32 kRewritePaddingWord = kEmptyCamWord;

// Words of cam `camNumber` (1..125).
inline int camOnWord(int camNumber) {
    return 2 * camNumber - 1;
}
inline int camOffWord(int camNumber) {
    return 2 * camNumber;
}

// Words to write to one area, from `firstWord`.
struct TrackWrite {
    int firstWord = kFirstCamWord;
    QList<qint32> words;
    friend bool operator==(const TrackWrite& a, const TrackWrite& b) {
        return a.firstWord == b.firstWord && a.words == b.words;
    }
};

// Replaces the whole track with `cams` (at most 125, ordered as they should
// be numbered): words from word 1, at least 2 cams. An invalid-data error
// for a cam the device would read as empty (a point of 0x80000000) or as a
// deletion (equal points).
Result<TrackWrite> wholeTrackWrite(const QList<Cam>& cams);
// Changes, or creates in an empty place, cam `camNumber` only.
Result<TrackWrite> singleCamWrite(int camNumber, const Cam& cam);
// Deletes cam `camNumber` (equal points).
Result<TrackWrite> camDeleteWrite(int camNumber);

// The cams in track words as read from word 1 (an even count, pairs);
// empty places are skipped. An invalid-data error for a half-empty pair or
// one with equal points, which no device reports for a real cam.
Result<QList<Cam>> camsFromTrackWords(const QList<qint32>& words);

}  // namespace cambench::comm::table
