#include "device_info.h"

namespace cambench {

bool operator==(const DeviceInfo& a, const DeviceInfo& b) {
    return a.epromDate == b.epromDate && a.deviceNumber == b.deviceNumber &&
           a.protocol == b.protocol && a.outputs == b.outputs && a.inputs == b.inputs &&
           a.deadTimeOutputs == b.deadTimeOutputs && a.programs == b.programs &&
           a.minPosition == b.minPosition && a.maxPosition == b.maxPosition &&
           a.maxDeadTime == b.maxDeadTime && a.cpuClock == b.cpuClock &&
           a.temperature == b.temperature && a.freeCams == b.freeCams &&
           a.programmedCams == b.programmedCams && a.programmedDeadTimes == b.programmedDeadTimes &&
           a.ramSize == b.ramSize && a.ramFree == b.ramFree &&
           a.serialEepromSize == b.serialEepromSize && a.parallelEepromSize == b.parallelEepromSize;
}

DeviceIdentity camConIdentity(const DeviceInfo& info) {
    DeviceIdentity identity;
    const auto number = [&](const char* key, qint64 value) {
        identity.set(QLatin1String(key), QString::number(value));
    };
    identity.set(QStringLiteral("eprom"), info.epromDate);
    number("device", info.deviceNumber);
    number("outputs", info.outputs);
    number("inputs", info.inputs);
    number("dead-time outputs", info.deadTimeOutputs);
    number("programs", info.programs);
    identity.set(QStringLiteral("actual values"),
                 QStringLiteral("%1..%2").arg(info.minPosition).arg(info.maxPosition));
    number("max dead time", info.maxDeadTime);
    number("cpu clock", info.cpuClock);
    number("ram", info.ramSize);
    number("serial eeprom", info.serialEepromSize);
    number("parallel eeprom", info.parallelEepromSize);
    return identity;
}

bool sameDevice(const DeviceInfo& before, const DeviceInfo& now, bool compareContents) {
    const bool identity = camConIdentity(before) == camConIdentity(now);
    if (!identity || !compareContents) return identity;
    return before.freeCams == now.freeCams && before.programmedCams == now.programmedCams &&
           before.programmedDeadTimes == now.programmedDeadTimes;
}

}  // namespace cambench
