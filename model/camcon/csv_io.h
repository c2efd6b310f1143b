#pragma once

#include "analogue_cams.h"
#include "cam_program.h"
#include "dead_time_modes.h"
#include "dead_times.h"
#include "model/result.h"

#include <QByteArray>
#include <QMap>
#include <QString>

namespace cambench {

// Cam tracks by output (1-based), as in CamProgram::tracks.
using Tracks = QMap<int, Track>;

// CSV exchange for spreadsheets. UTF-8, "\n" line ends, a fixed header:
//   cams        "output,cam,on,off"  (cam = 1-based index within the track)
//   dead times  "output,deadtime"     (0.1 ms units)
//   names       "kind,number,name"    (kind output|program; names may be
//                                      quoted, "" stands for one ")
// Export writes rows sorted by output / kind and number; cams in
// switch-on order. Import is all-or-nothing: the first bad line is reported
// with its line number and reason, and nothing is returned. Blank lines are
// skipped. Import checks the format only; validate the result against the
// device (cam_validation.h, data_validation.h) before sending it.

QByteArray camsToCsv(const Tracks& tracks);
Result<Tracks> camsFromCsv(const QByteArray& content);

QByteArray deadTimesToCsv(const DeadTimes& deadTimes);
Result<DeadTimes> deadTimesFromCsv(const QByteArray& content);

// Dead times with their modes, as the table interface has them:
//   "output,deadtime,mode,on,off" (0.1 ms; mode normal|on/off|path-time;
//   deadtime is the mode normal's, on and off the other modes')
// A file in either form reads as a DeadTimeTable: plain dead times leave
// `modes` empty, a file with modes leaves `deadTimes` empty.
struct DeadTimeTable {
    DeadTimes deadTimes;
    DeadTimeModes modes;
};
QByteArray deadTimeModesToCsv(const DeadTimeModes& modes);
Result<DeadTimeTable> deadTimeTableFromCsv(const QByteArray& content);

// Analogue cams (table interface): "output,position,value", one row per
// base point in position order; a row "3,," says analogue output 3 has no
// points (the file then clears them). Outputs in ascending order.
QByteArray analogueCamsToCsv(const QList<AnalogueCamTrack>& tracks);
Result<QList<AnalogueCamTrack>> analogueCamsFromCsv(const QByteArray& content);

QByteArray namesToCsv(const Names& names);
Result<Names> namesFromCsv(const QByteArray& content);

// File wrappers: errors start with the file's path; writing is atomic.
Status saveCamsCsv(const QString& path, const Tracks& tracks);
Result<Tracks> loadCamsCsv(const QString& path);
Status saveDeadTimesCsv(const QString& path, const DeadTimes& deadTimes);
Result<DeadTimes> loadDeadTimesCsv(const QString& path);
Result<DeadTimeTable> loadDeadTimeTableCsv(const QString& path);
Result<QList<AnalogueCamTrack>> loadAnalogueCamsCsv(const QString& path);
Result<Names> loadNamesCsv(const QString& path);

}  // namespace cambench
