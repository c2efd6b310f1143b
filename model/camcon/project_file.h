#pragma once

#include "analogue_cams.h"
#include "cam_program.h"
#include "dead_time_modes.h"
#include "dead_times.h"
#include "device_info.h"
#include "model/result.h"
#include "plc_network.h"
#include "programming_program.h"
#include "system_settings.h"
#include "user.h"

#include <QByteArray>
#include <QDateTime>
#include <QList>
#include <QMap>
#include <QString>
#include <QStringList>

#include <optional>

namespace cambench {

// The parts of a project that are read from a device as a whole.
enum class ProjectPart {
    Device,  // identity and capacities
    Settings,
    DeadTimes,
    OutputNames,
    Users,
    PlcNetworks,
    DeadTimeModes,       // table interface only
    AnalogueCams,        // table interface only
    ProgrammingProgram,  // table interface only
    EepromLock,          // table interface only
};

// Which parts of a project were read from a device, and when (UTC). A part
// without a time was not read: its content (if any) was made on the PC.
// Programs are read one by one: a program in Project::programs without a
// time here was made or loaded on the PC; a program absent from
// Project::programs is "not read" (unknown), which is not the same as an
// empty program (present, without tracks).
struct ProjectReadTimes {
    QMap<ProjectPart, QDateTime> parts;
    QMap<int, QDateTime> programs;  // key = program number

    bool isEmpty() const { return parts.isEmpty() && programs.isEmpty(); }
    friend bool operator==(const ProjectReadTimes& a, const ProjectReadTimes& b) {
        return a.parts == b.parts && a.programs == b.programs;
    }
};

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
    // User numbers are access codes: a project holds them only when they
    // were read and the file was saved with them (ProjectSaveOptions); a
    // user without a number keeps the device's number when written.
    QList<User> users;
    QList<PlcNetwork> plcNetworks;
    // Dead-time modes and separate switch-on/switch-off dead times, which
    // only the table interface reaches. Empty: the project has none (read
    // over another protocol, or made on the PC). Each output's `normal` is
    // the same device word as its entry in `deadTimes` (validateProject).
    DeadTimeModes deadTimeModes;
    // Analogue cams (table interface), ordered by analogue output; an
    // output listed is written whole (no points: none on the device).
    QList<AnalogueCamTrack> analogueCams;
    // The table interface's programming program and how the device changes
    // to it; empty: the project says nothing about it.
    std::optional<ProgrammingProgram> programmingProgram;
    // The table interface's EEPROM write lock (true: changes stay in RAM);
    // empty: the project says nothing about it.
    std::optional<bool> eepromLock;
    // The user's minimum pulse per output for the timing check (PC only).
    MinimumPulses minimumPulses;
    ProjectReadTimes readAt;

    friend bool operator==(const Project& a, const Project& b) {
        return a.device == b.device && a.programs == b.programs && a.deadTimes == b.deadTimes &&
               a.names == b.names && a.settings == b.settings && a.users == b.users &&
               a.plcNetworks == b.plcNetworks && a.deadTimeModes == b.deadTimeModes &&
               a.analogueCams == b.analogueCams && a.programmingProgram == b.programmingProgram &&
               a.eepromLock == b.eepromLock && a.minimumPulses == b.minimumPulses &&
               a.readAt == b.readAt;
    }
};

constexpr int kProjectFormatVersion = 1;

struct ProjectSaveOptions {
    // User numbers are written only when asked for: a file with them must
    // be kept like a key.
    bool includeUserNumbers = false;
};

// What is wrong with the values: cams (against `device` and the axis type
// in `settings`), dead times, names, users, PLC networks, settings,
// duplicate numbers. Warnings: a project with them still loads and saves
// (a device may hold such values); writing it to a device is refused.
// Users without a number are not a problem here. Empty when valid.
QStringList validateProject(const Project& project);

// The file content. Keys sorted, integers only, cams as [on, off] pairs,
// lists in their in-memory order: the same project gives the same bytes.
// "readAt": {"device": ISO time, ..., "programs": [{"program": 0, "time": ...}]}.
QByteArray projectToJson(const Project& project, const ProjectSaveOptions& options = {});
// Checks format, version and the structure: types, numbers that name
// outputs, programs and areas the project's device has, nothing twice.
// Values the device could hold load as they are (see validateProject); the
// error names the first problem with its JSON path. Users get all 256
// output access entries.
Result<Project> projectFromJson(const QByteArray& bytes);

// Writes atomically, whatever validateProject says.
Status saveProject(const QString& path, const Project& project,
                   const ProjectSaveOptions& options = {});
Result<Project> loadProject(const QString& path);

}  // namespace cambench
