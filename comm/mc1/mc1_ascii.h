#pragma once

#include "mc1_address.h"

#include "model/result.h"

#include <QByteArray>

#include <optional>

namespace cambench::comm {

// The MC100's ASCII protocol (docs/protocols/mc1.md, "ASCII"): one line each
// way, ended by CR (LF ignored). `Vn=?` → the value in decimal; `Vn=v` →
// OK; `Mn=?`, `An=?`, `En=?` → 1 or 0; `Mn=0|1`, `An=0|1` → OK; every
// error → ERR. Variables are signed 24 bit; inputs cannot be written. A
// device speaks binary or ASCII, not both.
constexpr qint32 kMc1Ascii24Min = -(1 << 23);
constexpr qint32 kMc1Ascii24Max = (1 << 23) - 1;

QByteArray mc1AsciiReadVariable(int number);
Result<QByteArray> mc1AsciiWriteVariable(int number, qint32 value);
QByteArray mc1AsciiReadPoint(const Mc1Point& point);
// Refused for an input.
Result<QByteArray> mc1AsciiWritePoint(const Mc1Point& point, bool on);

// An answer line: a number, a bit, or OK; ERR is the controller's refusal.
Result<qint32> mc1AsciiValue(const QByteArray& line);
Result<bool> mc1AsciiBit(const QByteArray& line);
Status mc1AsciiOk(const QByteArray& line);

// A request line as the controller reads it (lower case and spaces
// accepted): for the simulator.
struct Mc1AsciiRequest {
    enum class Target { Variable, Point };
    Target target = Target::Variable;
    int number = 0;               // the variable's number
    Mc1Point point;               // Target::Point
    std::optional<qint32> value;  // none: a query ("=?")
};
std::optional<Mc1AsciiRequest> parseMc1AsciiRequest(const QByteArray& line);

}  // namespace cambench::comm
