#pragma once

// The project file's sections that only the table interface reaches, beside
// the dead-time modes: "analogueCams": [{"output": 1, "points": [[position,
// value], ...]}, ...], "programmingProgram": {"program": 0, "selectMode":
// "slow", "switchValue": 0} and "eepromLock": true. Each is optional: a file
// without it has nothing to say about the section.

#include "analogue_cams.h"
#include "model/json_reader.h"
#include "programming_program.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QList>

namespace cambench {

QJsonArray analogueCamsToJson(const QList<AnalogueCamTrack>& tracks);
// Outputs 1..14, each once; points as [position, value] pairs. Values are
// checked by validateAnalogueCamTrack, not here.
QList<AnalogueCamTrack> analogueCamsFromJson(JsonReader& reader, const QJsonArray& array,
                                             const QString& path);

QJsonObject programmingProgramToJson(const ProgrammingProgram& programming);
ProgrammingProgram programmingProgramFromJson(JsonReader& reader, const QJsonObject& object,
                                              const QString& path);

}  // namespace cambench
