#pragma once

// What the one write path (write_items.h) is asked to write. Every item
// carries the value wanted on the device and, when the caller knows it, the
// value the caller believes the device holds (from its last read). GUI and
// CLI build plans; writeItems() checks and writes them.

#include "model/camcon/cam_program.h"
#include "model/camcon/plc_network.h"
#include "model/camcon/project_file.h"
#include "model/camcon/system_settings.h"
#include "model/camcon/user.h"
#include "model/camcon/workspace_item.h"

#include <QList>
#include <QString>

#include <optional>

namespace cambench::usecases {

// The cams of one output in one program; the device's track becomes
// exactly `wanted` (an empty track deletes every cam of that output).
// `believed` is informative only: the track is always read right before it
// is written, so that only the cams that differ are sent.
struct TrackWrite {
    int program = 0;
    Track wanted;
    std::optional<Track> believed;
};

// Dead-time compensation of one output (1-based), in 0.1 ms steps.
struct DeadTimeWrite {
    int output = 1;
    qint32 wanted = 0;
    std::optional<qint32> believed;
};

// The dead-time mode and its dead times of one output (1-based), which only
// the table interface reaches. `wanted.normal` is the same device word as
// the output's DeadTimeWrite: a plan holds one value for it.
struct DeadTimeModeWrite {
    int output = 1;
    OutputDeadTime wanted;
    std::optional<OutputDeadTime> believed;
};

// The base points of one analogue output (table interface); the device's
// points become exactly `wanted.points`.
struct AnalogueCamWrite {
    AnalogueCamTrack wanted;
    std::optional<AnalogueCamTrack> believed;
};

// The table interface's programming program and select mode.
struct ProgrammingProgramWrite {
    ProgrammingProgram wanted;
    std::optional<ProgrammingProgram> believed;
};

// The table interface's EEPROM write lock (true: later changes stay in RAM).
struct EepromLockWrite {
    bool wanted = false;
    std::optional<bool> believed;
};

// An output name (number = output, 1-based) or a program name (number =
// program, 0-based).
struct NameWrite {
    int number = 0;
    QString wanted;
    std::optional<QString> believed;
};

// One group of settings (SettingSpec::group, e.g. "encoder"): `wanted`
// holds the keys to set. Keys whose wanted value equals the device's are
// left alone; read-only keys are refused by the check.
struct SettingsWrite {
    QString group;
    SystemSettings wanted;
};

// A user: new (deviceNumber empty), changed, or deleted (wanted empty).
// `deviceNumber` is the number the user has on the device now. A wanted
// user without a number (a project saved without user numbers) keeps the
// number of the device's user with the same name. What the device holds
// before is WritePlan::usersOnDevice (read by writeItems when absent: the
// check needs every user for duplicate numbers anyway).
// `row`: the row of the workspace's user list it stands for (the GUI's;
// -1: a user deleted there, or a plan not made from a workspace).
struct UserWrite {
    QString deviceNumber;
    std::optional<User> wanted;
    int row = -1;
};

// One PLC network; identified by its area and number.
struct PlcWrite {
    PlcNetwork wanted;
    std::optional<PlcNetwork> believed;
};

// Everything one write is to do. Items are written in this order:
// settings, program names, tracks, dead times, dead-time modes, analogue
// cams, output names, users, PLC networks, the programming program
// (settings first: the axis type decides which cams are valid; the
// programming program last: writing cams over the table interface selects
// their program). An EEPROM unlock comes before everything, so that what
// follows is stored; a lock after everything, so that it is stored first.
struct WritePlan {
    QList<SettingsWrite> settings;
    QList<NameWrite> programNames;
    QList<TrackWrite> tracks;
    QList<DeadTimeWrite> deadTimes;
    QList<DeadTimeModeWrite> deadTimeModes;
    QList<NameWrite> outputNames;
    QList<UserWrite> users;
    QList<PlcWrite> plcNetworks;
    QList<AnalogueCamWrite> analogueCams;
    std::optional<ProgrammingProgramWrite> programmingProgram;
    std::optional<EepromLockWrite> eepromLock;

    // What the caller read from the device: the settings (passed on as the
    // device's values, so nothing is read twice; also gives the axis type
    // and the PLC counts for the check) and the users (for the check of
    // duplicate numbers). Read by writeItems when absent and needed.
    std::optional<SystemSettings> settingsOnDevice;
    std::optional<QList<User>> usersOnDevice;

    // The communication settings (linkSettingKeys(): device number,
    // protocol) the person asked for by name. Only these of the settings
    // groups' communication settings are written, each on its own and last
    // of all, even after an EEPROM lock (over this connection nothing may
    // reach the device after them); every other one is left out and the
    // report names it. A project, a settings file or another device's copy
    // holds them as that device had them: written unasked, they would change
    // how this device is reached (issue 39).
    QStringList linkSettingsAsked;

    int itemCount() const;
    bool isEmpty() const { return itemCount() == 0; }
};

// The item each entry of a plan is about: the key its outcome carries
// (WriteReport), by which a report is paired with its plan.
WorkspaceItem itemOf(const TrackWrite& write);
WorkspaceItem itemOf(const DeadTimeWrite& write);
WorkspaceItem itemOf(const DeadTimeModeWrite& write);
// By `row`; without one (a deletion, a plan not made from a workspace) by
// the device number.
WorkspaceItem itemOf(const UserWrite& write);
WorkspaceItem itemOf(const PlcWrite& write);
WorkspaceItem itemOf(const AnalogueCamWrite& write);
WorkspaceItem programNameItem(const NameWrite& write);
WorkspaceItem outputNameItem(const NameWrite& write);

// Splits `wanted` into one SettingsWrite per settings group, in the order
// of settingSpecs(). Keys that are no setting go into a group "unknown"
// (which the check refuses).
QList<SettingsWrite> settingsGroups(const SystemSettings& wanted);

// The plan that makes the device hold `wanted` (a project), with the
// beliefs taken from `onDevice` (a project read from the device, e.g. by
// readEverything; parts it lacks are unknown). A program in `wanted`
// replaces the whole program: every output with cams in `wanted` gets its
// track, and every other output 1..onDevice.device.outputs an empty one.
// Users without a number in `wanted` keep the device's number of the user
// with the same name; device users the project does not name are left.
WritePlan planFromProject(const Project& wanted, const Project& onDevice);

}  // namespace cambench::usecases
