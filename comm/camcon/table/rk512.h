#pragma once

#include "model/result.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QList>
#include <QString>

#include <optional>

namespace cambench::comm::table {

// RK512 as the CamCon's table interface speaks it over 3964R (notes 7,
// table-interface manual 2.1.2.2.1): read ('E') and write ('A') of data
// blocks ('D') only, one telegram per request, no follow-up telegrams.
//
// Request: 00 00, order, 44, area, offset, word count (2 bytes BE, 16-bit
// words), FF FF, then the data of a write. Reply: 00 00 00, error number,
// then the data of a read. Data are big-endian.

// The device's two serial modes of the table interface ("Ser:" menu).
enum class Rk512Variant {
    N96,  // "3964R n96": 9600 8N1, the offset counts 32-bit table words
    E38,  // "3964R e38": 38400 8E1, the offset counts 16-bit words (Siemens DW)
};

// Everything that differs between the variants, in one table (rk512.cpp).
struct Rk512VariantInfo {
    Rk512Variant variant;
    const char* name;  // as the device's menu shows it
    int baudRate;
    char parity;              // 'N' none, 'E' even; 8 data bits, 1 stop bit
    int offsetsPerWord;       // offset units per 32-bit table word: 1 (n96) or 2 (e38)
    int reachableWords;       // table words 0..reachableWords-1 can be addressed
    const char* provisional;  // why this row is a guess, or nullptr
};
const Rk512VariantInfo& rk512VariantInfo(Rk512Variant variant);

enum class Rk512Order : quint8 {
    Read = 0x45,   // 'E': the device sends data
    Write = 0x41,  // 'A': the device takes data
};

inline constexpr quint8 kRk512DataBlock = 0x44;  // 'D'
inline constexpr int kRk512RequestHeaderBytes = 10;
inline constexpr int kRk512ReplyHeaderBytes = 4;
inline constexpr int kRk512MinWords16 = 2;   // one 32-bit table word
inline constexpr int kRk512MaxWords16 = 64;  // 128 data bytes, 32 table words

// The error numbers of the reply (manual 2.1.2.2.1).
enum class Rk512Error : quint8 {
    None = 0,
    UnknownBlockType = 16,  // only data blocks 'D'
    BeyondBlock = 20,       // beyond the end of the data area
    UnknownOrder = 22,      // only 'E' or 'A'
    TooMuchData = 52,       // more than 128 data bytes
    General = 54,
};
// What error `number` means and what to do about it; unknown numbers say so.
QString rk512ErrorText(quint8 number);

// A request with its fields as they travel (offset in the variant's unit,
// count in 16-bit words). rk512_planner.h builds them from table words.
struct Rk512Request {
    Rk512Order order = Rk512Order::Read;
    int area = 1;     // data area (block) 1..255
    int offset = 0;   // 0..255
    int words16 = 2;  // kRk512MinWords16..kRk512MaxWords16
    QByteArray data;  // a write's data, words16 * 2 bytes; empty for a read

    friend bool operator==(const Rk512Request& a, const Rk512Request& b) {
        return a.order == b.order && a.area == b.area && a.offset == b.offset &&
               a.words16 == b.words16 && a.data == b.data;
    }
};

// PC side: the request telegram, or a usage error naming the bad field.
Result<QByteArray> encodeRk512Request(const Rk512Request& request);
// PC side: the data of a read (words16 * 2 bytes) or nothing for a write;
// a device error (Error::deviceCode = the RK512 error number) or a
// communication error for a malformed reply.
Result<QByteArray> decodeRk512Reply(QByteArrayView telegram, const Rk512Request& request);

// Device side: a request, or the error number to answer with.
struct Rk512ParsedRequest {
    std::optional<Rk512Request> request;
    Rk512Error error = Rk512Error::None;
    QString detail;  // why, for the simulator's log
};
Rk512ParsedRequest parseRk512Request(QByteArrayView telegram, Rk512Variant variant);
// Device side: the reply telegram.
QByteArray encodeRk512Reply(Rk512Error error, QByteArrayView data = {});

// 32-bit table words <-> data bytes, big-endian. In e38 a table word is two
// 16-bit words, high word first (provisional, see rk512VariantInfo), which
// gives the same bytes.
QByteArray tableWordsToBytes(const QList<qint32>& words);
Result<QList<qint32>> bytesToTableWords(QByteArrayView bytes);

}  // namespace cambench::comm::table
