#pragma once

// Cam-BUS on the wire (docs/protocols/cambus.md): the byte kinds, the token, the
// data block with its 15-bit sum and block bit, and the pseudo-terminal's
// encoding of breaks (P12). Pure functions: the bus state machine
// (listening, mastership, turns) builds on them.

#include "comm/transport/break_marks.h"
#include "model/result.h"

#include <QByteArray>
#include <QList>

#include <optional>

namespace cambench::comm {

constexpr int kCamBusLastUser = 63;
constexpr int kCamBusDefaultPcNumber = 63;
constexpr quint8 kCamBusToken1 = 0xA5;
constexpr quint8 kCamBusToken2 = 0x37;
constexpr int kCamBusMaxData = 255;

// The four kinds of user byte: the user's number in the low six bits.
enum class CamBusByteKind : quint8 {
    Did = 0x00,  // DID (after the token) or TO (the destination)
    Ack = 0x40,  // transmit buffer full / receive queue has room / RID answer
    Nak = 0x80,  // transmit buffer empty / queue full / block received
    Rid = 0xC0,  // the master's search for user n in an init phase
};

inline quint8 camBusByte(CamBusByteKind kind, int user) {
    return quint8(quint8(kind) | (user & 0x3F));
}
inline CamBusByteKind camBusKind(quint8 byte) {
    return CamBusByteKind(byte & 0xC0);
}
inline int camBusUser(quint8 byte) {
    return byte & 0x3F;
}

// The token for `user`: A5 37 S S.
QByteArray camBusToken(int user);

// A data block: LEN, the data, CHK1 (block bit·0x80 + sum>>8), CHK2
// (sum & 0xFF); sum = LEN + data, 15 bits, not inverted (P6).
struct CamBusBlock {
    QByteArray data;  // 1..255 bytes: one CamCon frame with its checksum characters (P7)
    bool blockBit = false;
};

// The block's wire bytes; a usage error for no data or more than 255 bytes.
Result<QByteArray> encodeCamBusBlock(const CamBusBlock& block);
// The 15-bit sum of LEN and the data.
quint16 camBusSum(const QByteArray& lenAndData);

// Reading a block from the front of `bytes`: nullopt while incomplete; an
// InvalidData error for LEN 0 or a checksum that does not match (the
// receiver then stays silent, P5).
Result<std::optional<CamBusBlock>> takeCamBusBlock(QByteArray& bytes);

// P12's encoding of breaks (FF 00 00) and of a data byte FF (FF FF) is
// the serial line's, in comm/transport/break_marks.h.

}  // namespace cambench::comm
