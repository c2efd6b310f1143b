#pragma once

#include "comm/camcon/table/rk512.h"

#include <QList>
#include <QString>

namespace cambench::comm {

class SimDevice;

// What the simulated device answers one RK512 request with.
struct SimAreaReply {
    table::Rk512Error error = table::Rk512Error::None;
    QList<qint32> words;  // a read's words
    bool silent = false;  // no reply at all (the hardware reset of area 205)
    QString detail;       // why the error, for the simulator's log

    static SimAreaReply fail(table::Rk512Error error, QString detail) {
        SimAreaReply reply;
        reply.error = error;
        reply.detail = std::move(detail);
        return reply;
    }
};

// The data areas of the table-interface manual, chapter 3, over one
// SimDevice: the same cams, dead times, settings and PLC networks the ASCII
// commands reach (settings through the device's ASCII handlers, so both
// protocols check values alike), plus what only the table interface has
// (SimTableState). Words the map lists as free read 0. Areas the simulator
// does not have (214, 215, 217..240, 255, outputs beyond the profile)
// answer error 20.
class SimTableAreas {
public:
    explicit SimTableAreas(SimDevice& device) : m_device(device) {}

    SimAreaReply read(int area, int firstWord, int count);
    SimAreaReply write(int area, int firstWord, const QList<qint32>& values);

private:
    SimDevice& m_device;
};

// One file per group of areas (sim_table_*_words.cpp).
namespace sim_table {

// A word's value, or the error to answer a read with.
struct WordRead {
    qint32 value = 0;
    table::Rk512Error error = table::Rk512Error::None;
    QString detail;
};
inline WordRead refuse(table::Rk512Error error, QString detail) {
    return {0, error, std::move(detail)};
}

bool isTrackArea(const SimDevice& device, int area);  // 1..outputs, 241..240+channels
WordRead readTrackWord(SimDevice& device, int area, int word);
// Writes a run: the pairs of words 1..250 as one unit (whole-track rewrite).
SimAreaReply writeTrackWords(SimDevice& device, int area, int firstWord,
                             const QList<qint32>& values);

WordRead readStatusWord(SimDevice& device, int area, int word);  // 201, 202
SimAreaReply writeStatusWord(SimDevice& device, int area, int word, qint32 value);

WordRead readSettingWord(SimDevice& device, int area, int word);  // 203, 204, 205
SimAreaReply writeSettingWord(SimDevice& device, int area, int word, qint32 value);

WordRead readPlcWord(SimDevice& device, int area, int word);  // 206..213, 216
SimAreaReply writePlcWord(SimDevice& device, int area, int word, qint32 value);

// The program areas 1..200 read and write (area 201 word 70).
int programmingProgram(const SimDevice& device);

}  // namespace sim_table

}  // namespace cambench::comm
