#include "rk512.h"

#include <QCoreApplication>
#include <QtEndian>

namespace cambench::comm::table {

namespace {

// The offset is one byte in both variants (manual: "Start address (offset)
// 0 - 255"; notes 7 vector `05 0A`). n96 thus reaches all 256 table words;
// e38 counts 16-bit words, so only table words 0..127 fit in the byte.
constexpr Rk512VariantInfo kVariants[] = {
    {Rk512Variant::N96, "3964R n96", 9600, 'N', 1, 256, nullptr},
    {Rk512Variant::E38, "3964R e38", 38400, 'E', 2, 128,
     "provisional: the manual only says \"16-bit range (DW)\"; read as table word k = 16-bit "
     "words 2k (high) and 2k+1 (low), so table words 128..255 are out of reach"},
};

// Device side, a reading of ours: a count that does not fill whole table
// words, in n96, is answered with the general error (the manual names none).
constexpr Rk512Error kOddCountErrorN96 = Rk512Error::General;

constexpr quint8 kCoordinationOff = 0xFF;

QString describe(const Rk512Request& request) {
    // Whole phrases per order: a translation may need to word them differently.
    const QString text =
        request.order == Rk512Order::Read
            ? QCoreApplication::translate(
                  "cambench::comm", "RK512 read of data area %1 at offset %2 (%3 16-bit words)")
            : QCoreApplication::translate(
                  "cambench::comm", "RK512 write of data area %1 at offset %2 (%3 16-bit words)");
    return text.arg(request.area).arg(request.offset).arg(request.words16);
}

Rk512ParsedRequest refuse(Rk512Error error, QString detail) {
    Rk512ParsedRequest parsed;
    parsed.error = error;
    parsed.detail = std::move(detail);
    return parsed;
}

}  // namespace

const Rk512VariantInfo& rk512VariantInfo(Rk512Variant variant) {
    for (const Rk512VariantInfo& info : kVariants) {
        if (info.variant == variant) return info;
    }
    return kVariants[0];
}

QString rk512ErrorText(quint8 number) {
    switch (Rk512Error(number)) {
        case Rk512Error::None:
            return QCoreApplication::translate("cambench::comm", "No error.");
        case Rk512Error::UnknownBlockType:
            return QCoreApplication::translate(
                "cambench::comm",
                "Error 16, command unknown: the device serves only data blocks ('D'). The tool "
                "sent another block type; report this as a bug.");
        case Rk512Error::BeyondBlock:
            return QCoreApplication::translate(
                "cambench::comm",
                "Error 20, beyond the data block: the words asked for reach past the end of the "
                "data area, or the area does not exist on this device or firmware. Check the area "
                "and word numbers against the device's manual.");
        case Rk512Error::UnknownOrder:
            return QCoreApplication::translate(
                "cambench::comm",
                "Error 22, command unknown: the device knows only read ('E') and write ('A'). The "
                "tool sent another order; report this as a bug.");
        case Rk512Error::TooMuchData:
            return QCoreApplication::translate(
                "cambench::comm",
                "Error 52, too many data: more than 128 bytes (64 16-bit words) in one telegram. "
                "Split the transfer into smaller telegrams.");
        case Rk512Error::General:
            return QCoreApplication::translate(
                "cambench::comm",
                "Error 54, general error: the device refused the request, e.g. a write to a "
                "read-only word, a value out of range, or the EEPROM busy. Check the value and "
                "whether the word may be written, then try again.");
    }
    return QCoreApplication::translate(
               "cambench::comm",
               "Error %1, not listed in the manual: the device refused the request for a reason "
               "the tool does not know. Check the request and the device's display.")
        .arg(number);
}

Result<QByteArray> encodeRk512Request(const Rk512Request& request) {
    if (request.area < 1 || request.area > 255) {
        return Error::usage(QCoreApplication::translate(
                                "cambench::comm", "RK512: data area %1 does not exist (1..255).")
                                .arg(request.area));
    }
    if (request.offset < 0 || request.offset > 255) {
        return Error::usage(
            QCoreApplication::translate("cambench::comm",
                                        "RK512: offset %1 does not fit in the offset byte "
                                        "(0..255); split the transfer or use 3964R n96.")
                .arg(request.offset));
    }
    if (request.words16 < kRk512MinWords16 || request.words16 > kRk512MaxWords16) {
        return Error::usage(
            QCoreApplication::translate("cambench::comm",
                                        "RK512: %1 16-bit words in one telegram (%2..%3 "
                                        "allowed); split the transfer.")
                .arg(request.words16)
                .arg(kRk512MinWords16)
                .arg(kRk512MaxWords16));
    }
    const qsizetype expectedData = request.order == Rk512Order::Write ? request.words16 * 2 : 0;
    if (request.data.size() != expectedData) {
        return Error::usage(
            QCoreApplication::translate("cambench::comm", "%1 carries %2 data bytes, %3 expected.")
                .arg(describe(request))
                .arg(request.data.size())
                .arg(expectedData));
    }
    QByteArray telegram;
    telegram.reserve(kRk512RequestHeaderBytes + request.data.size());
    telegram.append('\0');
    telegram.append('\0');
    telegram.append(char(request.order));
    telegram.append(char(kRk512DataBlock));
    telegram.append(char(request.area));
    telegram.append(char(request.offset));
    telegram.append(char(request.words16 >> 8));
    telegram.append(char(request.words16 & 0xFF));
    telegram.append(char(kCoordinationOff));
    telegram.append(char(kCoordinationOff));
    telegram.append(request.data);
    return telegram;
}

Result<QByteArray> decodeRk512Reply(QByteArrayView telegram, const Rk512Request& request) {
    if (telegram.size() < kRk512ReplyHeaderBytes || telegram[0] != '\0' || telegram[1] != '\0' ||
        telegram[2] != '\0') {
        return Error::communication(
            QCoreApplication::translate(
                "cambench::comm",
                "%1: the reply is no RK512 reply (it must start with 00 00 00, got "
                "%2). Check that the device's serial mode is 3964R n96 or e38.")
                .arg(describe(request),
                     QString::fromLatin1(telegram.first(qMin<qsizetype>(telegram.size(), 8))
                                             .toByteArray()
                                             .toHex(' '))));
    }
    const quint8 error = quint8(telegram[3]);
    if (error != 0) {
        return Error::device(
            error, QStringLiteral("%1: %2").arg(describe(request), rk512ErrorText(error)));
    }
    const QByteArrayView data = telegram.sliced(kRk512ReplyHeaderBytes);
    const qsizetype expected = request.order == Rk512Order::Read ? request.words16 * 2 : 0;
    if (data.size() != expected) {
        return Error::communication(
            QCoreApplication::translate("cambench::comm",
                                        "%1: the reply carries %2 data bytes, %3 expected.")
                .arg(describe(request))
                .arg(data.size())
                .arg(expected));
    }
    return data.toByteArray();
}

Rk512ParsedRequest parseRk512Request(QByteArrayView telegram, Rk512Variant variant) {
    if (telegram.size() < kRk512RequestHeaderBytes) {
        return refuse(Rk512Error::General,
                      QStringLiteral("request of %1 bytes, shorter than the 10-byte header")
                          .arg(telegram.size()));
    }
    if (telegram[0] != '\0' || telegram[1] != '\0') {
        return refuse(Rk512Error::General, QStringLiteral("request does not start with 00 00"));
    }
    const quint8 order = quint8(telegram[2]);
    if (order != quint8(Rk512Order::Read) && order != quint8(Rk512Order::Write)) {
        return refuse(Rk512Error::UnknownOrder, QStringLiteral("order 0x%1 is neither 'E' nor 'A'")
                                                    .arg(order, 2, 16, QLatin1Char('0')));
    }
    if (quint8(telegram[3]) != kRk512DataBlock) {
        return refuse(Rk512Error::UnknownBlockType,
                      QStringLiteral("block type 0x%1 is not 'D'")
                          .arg(quint8(telegram[3]), 2, 16, QLatin1Char('0')));
    }
    Rk512Request request;
    request.order = Rk512Order(order);
    request.area = quint8(telegram[4]);
    request.offset = quint8(telegram[5]);
    request.words16 = (quint8(telegram[6]) << 8) | quint8(telegram[7]);
    if (quint8(telegram[8]) != kCoordinationOff || quint8(telegram[9]) != kCoordinationOff) {
        return refuse(Rk512Error::General, QStringLiteral("coordination flag is not FF FF"));
    }
    if (request.words16 > kRk512MaxWords16) {
        return refuse(Rk512Error::TooMuchData,
                      QStringLiteral("%1 16-bit words asked for").arg(request.words16));
    }
    if (request.area == 0 || request.words16 < kRk512MinWords16) {
        return refuse(
            Rk512Error::General,
            QStringLiteral("area %1, %2 16-bit words").arg(request.area).arg(request.words16));
    }
    const Rk512VariantInfo& info = rk512VariantInfo(variant);
    if (variant == Rk512Variant::N96 && request.words16 % 2 != 0) {
        return refuse(
            kOddCountErrorN96,
            QStringLiteral("%1 16-bit words do not fill whole table words").arg(request.words16));
    }
    // In 16-bit words, the unit of the count: where the request ends.
    const int unitsPerOffset = 2 / info.offsetsPerWord;
    const int end16 = request.offset * unitsPerOffset + request.words16;
    if (end16 > info.reachableWords * 2) {
        return refuse(Rk512Error::BeyondBlock,
                      QStringLiteral("offset %1 + %2 16-bit words reach past table word %3")
                          .arg(request.offset)
                          .arg(request.words16)
                          .arg(info.reachableWords - 1));
    }
    const QByteArrayView data = telegram.sliced(kRk512RequestHeaderBytes);
    const qsizetype expected = request.order == Rk512Order::Write ? request.words16 * 2 : 0;
    if (data.size() != expected) {
        return refuse(data.size() > expected ? Rk512Error::TooMuchData : Rk512Error::General,
                      QStringLiteral("%1 data bytes after the header, %2 expected")
                          .arg(data.size())
                          .arg(expected));
    }
    request.data = data.toByteArray();
    Rk512ParsedRequest parsed;
    parsed.request = request;
    return parsed;
}

QByteArray encodeRk512Reply(Rk512Error error, QByteArrayView data) {
    QByteArray telegram(3, '\0');
    telegram.append(char(error));
    telegram.append(data);
    return telegram;
}

QByteArray tableWordsToBytes(const QList<qint32>& words) {
    QByteArray bytes(words.size() * 4, '\0');
    for (qsizetype i = 0; i < words.size(); ++i) qToBigEndian(words[i], bytes.data() + i * 4);
    return bytes;
}

Result<QList<qint32>> bytesToTableWords(QByteArrayView bytes) {
    if (bytes.size() % 4 != 0) {
        return Error::communication(
            QCoreApplication::translate(
                "cambench::comm", "RK512: %1 data bytes do not make whole 32-bit table words.")
                .arg(bytes.size()));
    }
    QList<qint32> words;
    words.reserve(bytes.size() / 4);
    for (qsizetype i = 0; i < bytes.size(); i += 4) {
        words.append(qFromBigEndian<qint32>(bytes.data() + i));
    }
    return words;
}

}  // namespace cambench::comm::table
