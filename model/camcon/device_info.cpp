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

bool sameDevice(const DeviceInfo& before, const DeviceInfo& now, bool compareContents) {
    const bool identity =
        before.epromDate == now.epromDate && before.deviceNumber == now.deviceNumber &&
        before.outputs == now.outputs && before.inputs == now.inputs &&
        before.deadTimeOutputs == now.deadTimeOutputs && before.programs == now.programs &&
        before.minPosition == now.minPosition && before.maxPosition == now.maxPosition &&
        before.maxDeadTime == now.maxDeadTime && before.cpuClock == now.cpuClock &&
        before.ramSize == now.ramSize && before.serialEepromSize == now.serialEepromSize &&
        before.parallelEepromSize == now.parallelEepromSize;
    if (!identity || !compareContents) return identity;
    return before.freeCams == now.freeCams && before.programmedCams == now.programmedCams &&
           before.programmedDeadTimes == now.programmedDeadTimes;
}

}  // namespace cambench
