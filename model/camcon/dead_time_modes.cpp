#include "dead_time_modes.h"

#include <QCoreApplication>

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
        return QCoreApplication::translate(
                   "cambench::model",
                   "Output %1 has no dead-time compensation on this device (outputs "
                   "1..%2 have one).")
            .arg(output)
            .arg(device.deadTimeOutputs);
    }
    if (!deadTimeModeFromNumber(qint64(deadTime.mode))) {
        return QCoreApplication::translate(
                   "cambench::model",
                   "Output %1: dead-time mode %2 is unknown (0 normal, 1 on/off, 2 "
                   "path-time).")
            .arg(output)
            .arg(int(deadTime.mode));
    }
    // Whole sentences per value: a translation words each differently.
    const struct {
        qint32 value;
        const char* sentence;
    } values[] = {
        {deadTime.normal,
         QT_TRANSLATE_NOOP("cambench::model",
                           "Output %1: the dead time %2 is outside 0..%3 (0.1 ms), the device's "
                           "range.")},
        {deadTime.on, QT_TRANSLATE_NOOP("cambench::model",
                                        "Output %1: the switch-on dead time %2 is outside 0..%3 "
                                        "(0.1 ms), the device's range.")},
        {deadTime.off,
         deadTime.mode == DeadTimeMode::PathTime
             ? QT_TRANSLATE_NOOP("cambench::model",
                                 "Output %1: the switching time %2 is outside 0..%3 (0.1 ms), the "
                                 "device's range.")
             : QT_TRANSLATE_NOOP("cambench::model",
                                 "Output %1: the switch-off dead time %2 is outside 0..%3 (0.1 "
                                 "ms), the device's range.")},
    };
    for (const auto& item : values) {
        if (item.value >= 0 && item.value <= device.maxDeadTime) continue;
        return QCoreApplication::translate("cambench::model", item.sentence)
            .arg(output)
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
