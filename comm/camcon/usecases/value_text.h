#pragma once

// Device values as a person reads them in a write report (not part of the
// layer's API).

#include "model/camcon/analogue_cams.h"
#include "model/camcon/cam_program.h"
#include "model/camcon/dead_time_modes.h"
#include "model/camcon/plc_network.h"
#include "model/camcon/programming_program.h"
#include "model/camcon/system_settings.h"
#include "model/camcon/user.h"

#include <QString>

#include <optional>

namespace cambench::usecases {

QString camsText(const Track& track);   // "10..90, 180..270" or "no cams"
QString deadTimeText(qint32 tenthsMs);  // "32.1 ms"
// "on/off, switch-on 8.0 ms, switch-off 15.0 ms", "normal, 2.5 ms", ...
QString deadTimeModeText(const OutputDeadTime& deadTime);
QString nameText(const QString& name);               // "\"Pusher\"" or "no name"
QString settingsText(const SystemSettings& values);  // "cableLength=17, ..."
QString userText(const std::optional<User>& user);   // never the number
QString plcText(const PlcNetwork& network);          // "value 2500, reset 0, 2 symbols"
// "3 base points: 0 → 100, 1800 → -2000, 3599 → 0" or "no base points"
QString analogueCamsText(const AnalogueCamTrack& track);
// "program 3, select slow" / "program 3, select at the actual value 1200"
QString programmingProgramText(const ProgrammingProgram& programming);
QString eepromLockText(bool locked);  // "locked (changes stay in RAM)" / "unlocked"

// Labels of plan items.
QString trackLabel(int program, int output);  // "program 0, output 1"
QString deadTimeLabel(int output);            // "dead time of output 5"
QString deadTimeModeLabel(int output);        // "dead-time mode of output 5"
QString outputNameLabel(int output);          // "name of output 4"
QString programNameLabel(int program);        // "name of program 3"
QString settingsLabel(const QString& group, const SystemSettings& keys);
QString userLabel(const QString& name);         // "user \"Supervisor\""
QString plcLabel(const PlcNetwork& network);    // "PLC network M3"
QString analogueCamsLabel(int analogueOutput);  // "analogue output 2"
QString programmingProgramLabel();              // "programming program"
QString eepromLockLabel();                      // "EEPROM lock"

}  // namespace cambench::usecases
