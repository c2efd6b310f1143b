#pragma once

#include <QHashFunctions>
#include <QMetaType>
#include <QString>

namespace cambench {

// One item of the workspace that can differ from the device and be written
// on its own: what "Compare with device" lists and checks.
struct WorkspaceItem {
    enum class Kind {
        Track,        // program, number = output (1-based)
        ProgramName,  // program
        DeadTime,     // number = output
        OutputName,   // number = output
        Setting,      // key = setting key
        User,         // number = index into the workspace's users() (-1: none)
        DeletedUser,  // key = the user's number on the device
        PlcNetwork,   // number = DeviceWorkspace::plcKey(area, number)
        // The table interface's own sections.
        DeadTimeMode,        // number = output
        AnalogueCams,        // number = analogue output 1..14
        ProgrammingProgram,  // the programming program and its select mode
        EepromLock,
    };
    Kind kind = Kind::Track;
    int program = 0;
    int number = 0;
    QString key;

    static WorkspaceItem track(int program, int output) {
        return {Kind::Track, program, output, {}};
    }
    static WorkspaceItem programName(int program) { return {Kind::ProgramName, program, 0, {}}; }
    static WorkspaceItem deadTime(int output) { return {Kind::DeadTime, 0, output, {}}; }
    static WorkspaceItem outputName(int output) { return {Kind::OutputName, 0, output, {}}; }
    static WorkspaceItem setting(const QString& key) { return {Kind::Setting, 0, 0, key}; }
    static WorkspaceItem user(int index) { return {Kind::User, 0, index, {}}; }
    static WorkspaceItem deletedUser(const QString& number) {
        return {Kind::DeletedUser, 0, 0, number};
    }
    static WorkspaceItem plcNetwork(int key) { return {Kind::PlcNetwork, 0, key, {}}; }
    static WorkspaceItem deadTimeMode(int output) { return {Kind::DeadTimeMode, 0, output, {}}; }
    static WorkspaceItem analogueCams(int output) { return {Kind::AnalogueCams, 0, output, {}}; }
    static WorkspaceItem programmingProgram() { return {Kind::ProgrammingProgram, 0, 0, {}}; }
    static WorkspaceItem eepromLock() { return {Kind::EepromLock, 0, 0, {}}; }

    friend bool operator==(const WorkspaceItem& a, const WorkspaceItem& b) {
        return a.kind == b.kind && a.program == b.program && a.number == b.number && a.key == b.key;
    }
    friend size_t qHash(const WorkspaceItem& item, size_t seed = 0) {
        return qHashMulti(seed, int(item.kind), item.program, item.number, item.key);
    }
};

}  // namespace cambench

Q_DECLARE_METATYPE(cambench::WorkspaceItem)
