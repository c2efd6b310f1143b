#pragma once

#include <QByteArray>
#include <QByteArrayView>

namespace cambench::comm::table {

// The control characters of 3964R (notes 7, table-interface manual 2.1.2.2.2).
inline constexpr char kStx = '\x02';
inline constexpr char kEtx = '\x03';
inline constexpr char kDle = '\x10';
inline constexpr char kNak = '\x15';

// XOR of `bytes` as they travel, starting from `seed`. The BCC of a block is
// the XOR of every byte after STX up to and including ETX: a doubled DLE
// counts twice, and the STX is not in it (some public implementations XOR it
// in; the device does not).
quint8 bcc3964r(QByteArrayView bytes, quint8 seed = 0);

// What the sender writes after the partner's DLE: the telegram with every
// DLE doubled, then DLE ETX and the BCC. A BCC of 0x10 goes out once, not
// doubled, since the receiver takes the byte after DLE ETX as the BCC
// whatever it is.
QByteArray encodeBlock3964r(QByteArrayView telegram);

}  // namespace cambench::comm::table
