#pragma once

#include "mc1_variant.h"

#include <QtGlobal>

namespace cambench::comm {

// Numbers the MC-1 protocol manual leaves to the MC-1B programming manual,
// which we lack (docs/protocols/mc1.md): every one is provisional and lives
// here only, one line each in comm/mc1/README.md.

// Variables a backup saves by default: V1..V1000 on every variant.
struct Mc1VariableRange {
    int first = 1;
    int last = 1000;
};
Mc1VariableRange mc1VariableRange(Mc1Variant variant);

// Logical axes 1..8 (MC200 V2; AXIS_NODATA/AXIS_DATA and RDTABLE).
constexpr int kMc1FirstAxis = 1;
constexpr int kMc1LastAxis = 8;

// What RDSTAT reads of an axis: parameter 0x1000 + 0x10 × axis + value.
enum class Mc1AxisValue { Position = 0, Target = 1, Status = 2 };
quint16 mc1AxisParameter(int axis, Mc1AxisValue value);
// Bits of the axis status parameter.
constexpr qint32 kMc1AxisMoving = 1;
constexpr qint32 kMc1AxisHomed = 2;
constexpr qint32 kMc1AxisError = 4;

// Memory (RDMEM, WRMEM: 16-bit addresses, provisional P1).
constexpr int kMc1MemorySize = 0x10000;
constexpr int kMc1MaxMemoryRead = 125;   // RDMEM's n
constexpr int kMc1MaxMemoryWrite = 121;  // WRMEM's n
constexpr int kMc1MaxBlockRead = 56;     // RDBLOCK's n (MC100 V2)

}  // namespace cambench::comm
