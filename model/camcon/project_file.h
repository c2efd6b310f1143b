#pragma once

#include "cam_program.h"
#include "dead_times.h"
#include "device_info.h"
#include "plc_network.h"
#include "model/result.h"
#include "system_settings.h"
#include "user.h"

#include <QByteArray>
#include <QList>
#include <QString>
#include <QStringList>

namespace cambench {

// A whole device configuration for offline editing, saved as a versioned
// JSON file ({"format":"cambench-project","version":1,...}).
struct Project {
    DeviceInfo device;
    QList<CamProgram> programs;  // each with its number and name
    DeadTimes deadTimes;
    // Output names, and names of programs that need not be in `programs`.
    // A program in both places must carry the same name (validateProject).
    Names names;
    SystemSettings settings;
    QList<User> users;  // user numbers are access codes: keep the file private
    QList<PlcNetwork> plcNetworks;

    friend bool operator==(const Project& a, const Project& b) {
        return a.device == b.device && a.programs == b.programs && a.deadTimes == b.deadTimes &&
               a.names == b.names && a.settings == b.settings && a.users == b.users &&
               a.plcNetworks == b.plcNetworks;
    }
};

constexpr int kProjectFormatVersion = 1;

// Everything that would stop the project from being loaded again or written
// to the device: cams (against `device` and the axis type in `settings`),
// dead times, names, users, PLC networks, settings, duplicate numbers.
// Empty when valid.
QStringList validateProject(const Project& project);

// The file content. Keys sorted, integers only, cams as [on, off] pairs,
// lists in their in-memory order: the same project gives the same bytes.
QByteArray projectToJson(const Project& project);
// Checks format, version and every value; the error names the first
// problem with its JSON path. Users get all 256 output access entries.
Result<Project> projectFromJson(const QByteArray& bytes);

// Refuses an invalid project (validateProject) and writes atomically.
Status saveProject(const QString& path, const Project& project);
Result<Project> loadProject(const QString& path);

}  // namespace cambench
