#pragma once

#include "mc1_variant.h"

#include "model/result.h"

#include <QMap>
#include <QString>
#include <QtGlobal>

#include <optional>

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

// What RDSTAT reads of an axis.
enum class Mc1AxisValue { Position, Target, Status };
// "position", "target", "status": the names a parameter table file uses.
QString mc1AxisValueName(Mc1AxisValue value);
// Bits of the axis status parameter.
constexpr qint32 kMc1AxisMoving = 1;
constexpr qint32 kMc1AxisHomed = 2;
constexpr qint32 kMc1AxisError = 4;

// The RDSTAT/WRSTAT parameter numbers of the axes' values. They are the
// controller's (its MC-1B manual); CamBench has only a guess built in, so
// values read through it are provisional. The controller's own table is
// loaded from a CSV file of `name,axis,parameter` lines.
struct Mc1AxisParameterTable {
    // Where the numbers come from, for a person: the file, or the guess.
    QString source;
    // True for the built-in guess: what is read through it is not a fact.
    bool provisional = true;
    QMap<std::pair<int, Mc1AxisValue>, quint16> numbers;

    // The parameter number of `value` of `axis`; none when the table lacks it.
    std::optional<quint16> number(int axis, Mc1AxisValue value) const;
};

// The built-in guess: parameter 0x1000 + 0x10 × axis + 0 (position),
// 1 (target), 2 (status), for axes 1..8. Marked provisional.
Mc1AxisParameterTable mc1ProvisionalAxisParameters();
// The same layout from `base` on (the simulator of a controller whose
// numbers are not the guess); not provisional: the simulator's own.
Mc1AxisParameterTable mc1AxisParametersFrom(quint16 base, const QString& source);

// A parameter table file's text: one `name,axis,parameter` line each (name
// position, target or status; axis 1..8; parameter 0..65535, decimal or
// 0x hex); blank lines, lines starting with '#' and a first line
// `name,axis,parameter` are skipped. A malformed line refuses the whole
// file, naming the line and what is wrong.
Result<Mc1AxisParameterTable> parseMc1AxisParameterTable(const QByteArray& text,
                                                         const QString& source);
// The file at `path` read and parsed, its path the table's source.
Result<Mc1AxisParameterTable> loadMc1AxisParameterTable(const QString& path);

// Memory (RDMEM, WRMEM: 16-bit addresses, provisional P1).
constexpr int kMc1MemorySize = 0x10000;
constexpr int kMc1MaxMemoryRead = 125;   // RDMEM's n
constexpr int kMc1MaxMemoryWrite = 121;  // WRMEM's n
constexpr int kMc1MaxBlockRead = 56;     // RDBLOCK's n (MC100 V2)

}  // namespace cambench::comm
