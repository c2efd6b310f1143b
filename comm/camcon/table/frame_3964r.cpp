#include "frame_3964r.h"

namespace cambench::comm::table {

quint8 bcc3964r(QByteArrayView bytes, quint8 seed) {
    quint8 bcc = seed;
    for (char c : bytes) bcc ^= quint8(c);
    return bcc;
}

QByteArray encodeBlock3964r(QByteArrayView telegram) {
    QByteArray block;
    block.reserve(telegram.size() * 2 + 3);
    for (char c : telegram) {
        block.append(c);
        if (c == kDle) block.append(kDle);
    }
    block.append(kDle);
    block.append(kEtx);
    block.append(char(bcc3964r(block)));
    return block;
}

}  // namespace cambench::comm::table
