#pragma once

#include "device_info.h"

#include <QJsonObject>

namespace cambench {

class JsonReader;

// The identity and capacities of a device as stored in project and EEPROM
// image files. Every member is written; reading checks each against the
// range the manual allows.
QJsonObject deviceInfoToJson(const DeviceInfo& info);
DeviceInfo readDeviceInfo(JsonReader& reader, const QJsonObject& object, const QString& path);

}  // namespace cambench
