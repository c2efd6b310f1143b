#pragma once

// The decoded content of a CamCon backup (issue 36, item 2;
// EepromImage::content) and what differs between two of them, item by
// item in the CamCon's terms.

#include "project_file.h"

#include "model/backup_difference.h"

#include <QJsonObject>
#include <QList>

namespace cambench {

// The project as a backup holds it: a project file's object without the
// read times and without the device (the image records that; its free
// memory and temperature change by themselves), users without their
// numbers (access codes stay in the blocks only).
QJsonObject projectContentJson(const Project& project);
// Back to a project of `device` (the image's), to compare; InvalidData
// naming the first problem.
Result<Project> projectFromContent(const QJsonObject& content, const DeviceInfo& device);

// What differs from `before` to `after`: per program its name and its
// cams, output by output ("program 0, output 5: cam 100–200 added",
// "program 0, output 5: cam 100–200 → 100–250", "program 3: name \"A\" →
// \"B\""), then the device's other content part by part: dead times and
// output names by output ("output 5: deadTime 12 → 20"), settings
// ("setting axisLength: 360 → 720"), users by their place ("user 2: name
// ..."), PLC networks, the table interface's parts.
QList<BackupDifference> diffProjectContent(const Project& before, const Project& after);

}  // namespace cambench
