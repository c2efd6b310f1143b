#pragma once

#include "sim_device.h"

namespace cambench::comm::sim_util {

// Both points of an empty track or a search past either end (notes 3).
constexpr qint64 kNoCam = -qint64(0x80000000LL);  // 0x80000000 as a signed 32-bit field

inline bool validProgram(const SimDevice& device, qint64 program) {
    return program >= 0 && program < device.profile().programs;
}
inline bool validOutput(const SimDevice& device, qint64 output) {
    return output >= 0 && output < device.profile().outputs;
}

// Status table bytes of `count` bits, bit 0 of byte 0 = number 0 (notes 2).
QByteArray bitTable(int count, const std::function<bool(int)>& isSet);

}  // namespace cambench::comm::sim_util
