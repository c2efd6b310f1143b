#include "dead_time_modes.h"

namespace cambench {

namespace {

struct ModeName {
    DeadTimeMode mode;
    const char* key;
};
const ModeName kModeNames[] = {
    {DeadTimeMode::Normal, "normal"},
    {DeadTimeMode::SeparateOnOff, "on/off"},
    {DeadTimeMode::PathTime, "path-time"},
};

}  // namespace

QString deadTimeModeKey(DeadTimeMode mode) {
    for (const ModeName& name : kModeNames) {
        if (name.mode == mode) return QLatin1String(name.key);
    }
    return QString::number(int(mode));
}

std::optional<DeadTimeMode> deadTimeModeFromKey(const QString& key) {
    for (const ModeName& name : kModeNames) {
        if (key == QLatin1String(name.key)) return name.mode;
    }
    return std::nullopt;
}

std::optional<DeadTimeMode> deadTimeModeFromNumber(qint64 number) {
    for (const ModeName& name : kModeNames) {
        if (qint64(name.mode) == number) return name.mode;
    }
    return std::nullopt;
}

QString outputDeadTimeProblem(int output, const OutputDeadTime& deadTime,
                              const DeviceInfo& device) {
    if (output < 1 || output > device.deadTimeOutputs) {
        return QStringLiteral(
                   "Output %1 has no dead-time compensation on this device (outputs "
                   "1..%2 have one).")
            .arg(output)
            .arg(device.deadTimeOutputs);
    }
    if (!deadTimeModeFromNumber(qint64(deadTime.mode))) {
        return QStringLiteral(
                   "Output %1: dead-time mode %2 is unknown (0 normal, 1 on/off, 2 "
                   "path-time).")
            .arg(output)
            .arg(int(deadTime.mode));
    }
    const struct {
        qint32 value;
        const char* what;
    } values[] = {
        {deadTime.normal, "dead time"},
        {deadTime.on, "switch-on dead time"},
        {deadTime.off,
         deadTime.mode == DeadTimeMode::PathTime ? "switching time" : "switch-off dead time"},
    };
    for (const auto& item : values) {
        if (item.value >= 0 && item.value <= device.maxDeadTime) continue;
        return QStringLiteral(
                   "Output %1: the %2 %3 is outside 0..%4 (0.1 ms), the device's "
                   "range.")
            .arg(output)
            .arg(QLatin1String(item.what))
            .arg(item.value)
            .arg(device.maxDeadTime);
    }
    return {};
}

QStringList validateDeadTimeModes(const DeadTimeModes& modes, const DeviceInfo& device) {
    QStringList problems;
    for (auto it = modes.begin(); it != modes.end(); ++it) {
        const QString problem = outputDeadTimeProblem(it.key(), it.value(), device);
        if (!problem.isEmpty()) problems.append(problem);
    }
    return problems;
}

}  // namespace cambench
