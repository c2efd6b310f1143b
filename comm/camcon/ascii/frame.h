#pragma once

#include <QByteArray>
#include <QByteArrayView>

#include <optional>

namespace cambench::comm {

// Framing variants of the CamCon ASCII protocol (notes 1).
enum class Framing { Standard, Multiuser };

constexpr char kQuery = '?';
constexpr char kCommand = '!';
constexpr char kReply = ':';
constexpr char kEsc = 0x1B;
constexpr char kCr = 0x0D;
constexpr char kLf = 0x0A;

// The three Multiuser header bytes: 0x40+source, 0x80+destination,
// 0xC0+block. Not part of the checksum.
struct MultiuserAddress {
    int source = 63;      // 0..63
    int destination = 0;  // 0..63
    int block = 0;        // 0..63
    friend bool operator==(const MultiuserAddress& a, const MultiuserAddress& b) {
        return a.source == b.source && a.destination == b.destination && a.block == b.block;
    }
};

// One decoded or to-be-encoded frame. `body` is everything between the lead
// character and the checksum (command letters + data), unescaped.
struct Frame {
    char lead = kQuery;  // '?', '!' or ':'
    QByteArray body;
    std::optional<MultiuserAddress> address;  // set for Multiuser framing
    bool hasChecksum = true;  // false only for !C0 (manual 4.3.1) or with checksums off

    friend bool operator==(const Frame& a, const Frame& b) {
        return a.lead == b.lead && a.body == b.body && a.address == b.address &&
               a.hasChecksum == b.hasChecksum;
    }
};

// ~(sum of bytes) & 0xFF over lead + body (unescaped), notes 1.
quint8 checksum(char lead, QByteArrayView body);

// Two upper-case hex characters.
QByteArray checksumText(quint8 sum);

// Wire bytes: [header] lead, body with CR and ESC escaped by ESC, checksum
// (unless !hasChecksum), CR LF.
QByteArray encodeFrame(const Frame& frame);

// Wire bytes of a body with every CR and ESC preceded by ESC.
QByteArray escapeBody(QByteArrayView body);

}  // namespace cambench::comm
