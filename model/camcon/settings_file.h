#pragma once

// The one reader and writer of settings as JSON: inside project files and
// as a settings file of its own (cambench-cli settings read/write):
// {"format":"cambench-settings","version":1,"settings":{"key":value,...}}.
// Device values always load and save: a value outside its range is kept
// (validateSettings() warns about it); only what is not a setting or has
// the wrong type (a text for a number) is refused.

#include "model/json_reader.h"
#include "model/result.h"
#include "system_settings.h"

#include <QByteArray>
#include <QJsonObject>

namespace cambench {

constexpr int kSettingsFileFormatVersion = 1;

QJsonObject settingsToJson(const SystemSettings& settings);
// Reads the object at `path` ("settings"); problems go to `reader`.
SystemSettings settingsFromJson(JsonReader& reader, const QJsonObject& object, const QString& path);

QByteArray settingsFileToJson(const SystemSettings& settings);
Result<SystemSettings> settingsFileFromJson(const QByteArray& bytes);
// Errors start with the file's path.
Result<SystemSettings> loadSettingsFile(const QString& path);

}  // namespace cambench
