#pragma once

#include "device_info.h"

#include <QMap>
#include <QString>
#include <QStringList>

#include <optional>

namespace cambench {

// How an output compensates the dead time of its actuator (table interface,
// data areas 1..200 word 251; notes 3). The ASCII protocol knows only the
// plain dead time of mode Normal.
enum class DeadTimeMode {
    Normal = 0,         // one dead time for the switch-on and the switch-off point
    SeparateOnOff = 1,  // a dead time for each point
    PathTime = 2,       // displacement-time cam: switch on early, stay on for a time
};

// One output's dead-time compensation, in 0.1 ms steps.
struct OutputDeadTime {
    DeadTimeMode mode = DeadTimeMode::Normal;
    qint32 normal = 0;  // mode Normal (word 0)
    qint32 on = 0;      // mode SeparateOnOff: the switch-on point's (word 252)
    qint32 off = 0;     // SeparateOnOff: the switch-off point's; PathTime: the switching time
                        // (word 253)

    friend bool operator==(const OutputDeadTime& a, const OutputDeadTime& b) {
        return a.mode == b.mode && a.normal == b.normal && a.on == b.on && a.off == b.off;
    }
    friend bool operator!=(const OutputDeadTime& a, const OutputDeadTime& b) { return !(a == b); }
};

// key = output (1-based)
using DeadTimeModes = QMap<int, OutputDeadTime>;

// "normal", "on/off", "path-time": the names files and the command line use.
QString deadTimeModeKey(DeadTimeMode mode);
std::optional<DeadTimeMode> deadTimeModeFromKey(const QString& key);
// The mode with this device number (word 251), or nullopt for an unknown one.
std::optional<DeadTimeMode> deadTimeModeFromNumber(qint64 number);

// Empty when `deadTime` fits the device; otherwise one sentence naming the
// output: "Output 3: the switch-on dead time 12000 is above the largest dead
// time 9999 (0.1 ms)."
QString outputDeadTimeProblem(int output, const OutputDeadTime& deadTime, const DeviceInfo& device);
// Outputs 1..deadTimeOutputs and every value 0..maxDeadTime.
QStringList validateDeadTimeModes(const DeadTimeModes& modes, const DeviceInfo& device);

}  // namespace cambench
