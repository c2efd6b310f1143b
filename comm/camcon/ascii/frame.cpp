#include "frame.h"

namespace cambench::comm {

namespace {

constexpr quint8 kHeaderSource = 0x40;
constexpr quint8 kHeaderDestination = 0x80;
constexpr quint8 kHeaderBlock = 0xC0;

}  // namespace

quint8 checksum(char lead, QByteArrayView body) {
    quint8 sum = quint8(lead);
    for (char c : body) sum = quint8(sum + quint8(c));
    return quint8(~sum);
}

QByteArray checksumText(quint8 sum) {
    static const char kDigits[] = "0123456789ABCDEF";
    QByteArray text(2, '0');
    text[0] = kDigits[sum >> 4];
    text[1] = kDigits[sum & 0x0F];
    return text;
}

QByteArray escapeBody(QByteArrayView body) {
    QByteArray out;
    out.reserve(body.size() + 8);
    for (char c : body) {
        if (c == kCr || c == kEsc) out.append(kEsc);
        out.append(c);
    }
    return out;
}

QByteArray encodeFrame(const Frame& frame) {
    QByteArray out;
    out.reserve(frame.body.size() + 10);
    if (frame.address) {
        // Numbers are 6 bits on the wire; masking keeps a bad value from
        // producing a byte outside its header range.
        out.append(char(kHeaderSource + (frame.address->source & 0x3F)));
        out.append(char(kHeaderDestination + (frame.address->destination & 0x3F)));
        out.append(char(kHeaderBlock + (frame.address->block & 0x3F)));
    }
    out.append(frame.lead);
    out.append(escapeBody(frame.body));
    if (frame.hasChecksum) out.append(checksumText(checksum(frame.lead, frame.body)));
    out.append(kCr);
    out.append(kLf);
    return out;
}

}  // namespace cambench::comm
