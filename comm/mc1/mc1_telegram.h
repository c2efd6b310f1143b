#pragma once

#include "model/result.h"

#include <QByteArray>

namespace cambench::comm {

// MC-1 telegrams (docs/protocols/mc1.md): opcode, checksum, data, both ways;
// multi-byte values little-endian. The checksum is the 8-bit sum of every
// byte but the second (itself), not inverted.
constexpr quint8 kMc1Ack = 0x80;
constexpr quint8 kMc1Nak = 0x87;
// MC100MA cards send it every 5 or 10 ms; a telegram must follow one at
// once, and it is skipped while waiting for an answer.
constexpr quint8 kMc1Sync = 0xFF;

quint8 mc1Checksum(const QByteArray& telegram);
// Opcode, checksum and data.
QByteArray mc1Telegram(quint8 opcode, const QByteArray& data);
// The length a telegram of this opcode has by the rule (opcode & 7) + 1;
// the catalogue names the exceptions.
int mc1FormulaLength(quint8 opcode);

// `value` in `bytes` little-endian bytes (two's complement for negatives).
QByteArray mc1LittleEndian(qint64 value, int bytes);
// The value of 1..4 little-endian bytes; `isSigned` sign-extends the top bit.
qint64 mc1FromLittleEndian(const QByteArray& bytes, bool isSigned);

}  // namespace cambench::comm
