#pragma once

#include "model/camcon/analogue_cams.h"
#include "model/camcon/dead_time_modes.h"

#include <QList>
#include <QMap>

#include <utility>

namespace cambench::comm {

// What a CamCon keeps that only its table interface reaches (data areas the
// ASCII commands have no word for). Kept beside SimState, not in it: the
// simulator's EEPROM image format (an ASCII backup) does not carry it.
struct SimTableState {
    QMap<int, OutputDeadTime> deadTimeModes;       // output (0-based); `normal` unused (?TZK)
    QMap<int, QList<AnaloguePoint>> analogueCams;  // analogue output (0-based), by position
    QMap<std::pair<int, int>, qint32> words;       // (area, index) -> a word with no other home
    bool eepromLocked = false;                     // area 205 word 4
    // Area 201 word 70; -1 = the active program (provisional power-on value).
    int programmingProgram = -1;
    qint32 plcLinkSelection = 0;  // area 216 word 0
};

}  // namespace cambench::comm
