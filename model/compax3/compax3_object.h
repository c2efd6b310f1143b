#pragma once

#include "model/result.h"

#include <QString>

namespace cambench {

// A Compax3 object by its number: index and subindex ("680.5"). The drive
// speaks of objects this way in its ASCII protocol (docs/protocols/compax3.md).
struct Compax3ObjectId {
    int index = 0;     // 0..65535
    int subindex = 0;  // 0..255

    // "680.5": how CamBench writes an object everywhere (files, CLI, GUI).
    QString text() const;
    friend bool operator==(const Compax3ObjectId& a, const Compax3ObjectId& b) {
        return a.index == b.index && a.subindex == b.subindex;
    }
    friend bool operator!=(const Compax3ObjectId& a, const Compax3ObjectId& b) { return !(a == b); }
    friend bool operator<(const Compax3ObjectId& a, const Compax3ObjectId& b) {
        return a.index != b.index ? a.index < b.index : a.subindex < b.subindex;
    }
};

inline size_t qHash(const Compax3ObjectId& id, size_t seed = 0) {
    return ::qHash(quint32(id.index) << 8 | quint32(id.subindex), seed);
}

// Every way a technician writes an object: "680.5", "680,5", "o680.5",
// "O 680,5", "O $2A8,5" ($ = hexadecimal, as on the drive). Upper or lower
// case, spaces anywhere. A usage error says what was expected.
Result<Compax3ObjectId> parseCompax3Object(const QString& text);

// A number in the drive's hexadecimal notation: "$" and upper-case digits,
// at least `digits` of them ("$4103", "$32").
QString compax3HexText(qint64 value, int digits = 0);

// A number as the drive reads it: always a decimal point, whatever the
// locale (a German "12,5" is a syntax error on the drive), no exponent,
// no trailing zeros ("12.5", "-3", "0.001").
QString compax3NumberText(double value);

}  // namespace cambench
