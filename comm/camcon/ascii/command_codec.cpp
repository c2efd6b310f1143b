#include "command_codec.h"

#include <QCoreApplication>

#include "protocol_log.h"

namespace cambench::comm {

namespace {

constexpr QByteArrayView kOk("OK");
constexpr QByteArrayView kErr("ERR");
constexpr int kErrorDigits = 8;

bool isRest(const FieldSpec& spec) {
    switch (spec.type) {
        case FieldType::TextRest:
        case FieldType::HexBytes:
            return true;
        case FieldType::Binary:
            return spec.width < 0;
        case FieldType::HexWords:
            return spec.count < 0;
        default:
            return false;
    }
}

QString fieldName(const FieldSpec& spec) {
    return QString::fromLatin1(spec.name);
}

QString commandName(const CommandSpec& spec) {
    return QLatin1Char(spec.kind) + QString::fromLatin1(spec.name);
}

// Upper-case hex of the low 4*width bits of `value`.
QByteArray hexDigits(quint64 value, int width) {
    static const char kDigits[] = "0123456789ABCDEF";
    QByteArray out(width, '0');
    for (int i = width - 1; i >= 0; --i) {
        out[i] = kDigits[value & 0xF];
        value >>= 4;
    }
    return out;
}

// Digits of either case; the device sends upper case.
std::optional<quint64> parseHex(QByteArrayView digits) {
    if (digits.isEmpty()) return std::nullopt;
    quint64 value = 0;
    for (char c : digits) {
        int digit;
        if (c >= '0' && c <= '9')
            digit = c - '0';
        else if (c >= 'A' && c <= 'F')
            digit = c - 'A' + 10;
        else if (c >= 'a' && c <= 'f')
            digit = c - 'a' + 10;
        else
            return std::nullopt;
        value = value << 4 | quint64(digit);
    }
    return value;
}

qint64 signExtend(quint64 value, int width) {
    const int bits = 4 * width;
    const quint64 signBit = quint64(1) << (bits - 1);
    return qint64((value ^ signBit) - signBit);
}

Error rangeError(const FieldSpec& spec, qint64 value, qint64 min, qint64 max) {
    return Error::invalidData(
        QCoreApplication::translate("cambench::comm",
                                    "The value %1 of field \"%2\" is outside %3..%4 (%5 "
                                    "hex digits); use a value in that range.")
            .arg(value)
            .arg(fieldName(spec))
            .arg(min)
            .arg(max)
            .arg(spec.width));
}

Result<qint64> numberOf(const FieldSpec& spec, const Fields& fields) {
    if (!fields.has(spec.name)) return qint64(0);
    bool ok = false;
    const qint64 value = fields.value(spec.name).toLongLong(&ok);
    if (!ok) {
        return Error::invalidData(QCoreApplication::translate(
                                      "cambench::comm", "Field \"%1\" needs a number, got \"%2\".")
                                      .arg(fieldName(spec), fields.value(spec.name).toString()));
    }
    return value;
}

Result<QByteArray> encodeHex(const FieldSpec& spec, qint64 value, bool isSigned) {
    const int bits = 4 * spec.width;
    const qint64 min = isSigned ? -(qint64(1) << (bits - 1)) : 0;
    const qint64 max = isSigned ? (qint64(1) << (bits - 1)) - 1 : (qint64(1) << bits) - 1;
    if (value < min || value > max) return rangeError(spec, value, min, max);
    return hexDigits(quint64(value), spec.width);
}

Result<QByteArray> encodeText(const FieldSpec& spec, const QByteArray& text, bool fixedWidth) {
    if (text.contains('\0')) {
        return Error::invalidData(
            QCoreApplication::translate("cambench::comm",
                                        "Field \"%1\" contains a NUL character; remove it.")
                .arg(fieldName(spec)));
    }
    if (!fixedWidth) return text;
    if (text.size() > spec.width - 1) {
        return Error::invalidData(
            QCoreApplication::translate(
                "cambench::comm",
                "The text \"%1\" of field \"%2\" is %3 characters long; at most %4 fit.")
                .arg(QString::fromLatin1(text), fieldName(spec))
                .arg(text.size())
                .arg(spec.width - 1));
    }
    QByteArray padded = text;
    padded.append(QByteArray(spec.width - text.size(), '\0'));
    return padded;
}

Result<QByteArray> encodeField(const FieldSpec& spec, const Fields& fields) {
    switch (spec.type) {
        case FieldType::Hex:
        case FieldType::SignedHex: {
            const Result<qint64> value = numberOf(spec, fields);
            if (!value) return value.error();
            return encodeHex(spec, *value, spec.type == FieldType::SignedHex);
        }
        case FieldType::Text:
            return encodeText(spec, fields.bytes(spec.name), true);
        case FieldType::TextRest:
            return encodeText(spec, fields.bytes(spec.name), false);
        case FieldType::Binary: {
            if (spec.width < 0) return fields.bytes(spec.name);
            if (!fields.has(spec.name)) return QByteArray(spec.width, '\0');
            const QByteArray data = fields.bytes(spec.name);
            if (data.size() != spec.width) {
                return Error::invalidData(
                    QCoreApplication::translate("cambench::comm",
                                                "Field \"%1\" needs exactly %2 bytes, got %3.")
                        .arg(fieldName(spec))
                        .arg(spec.width)
                        .arg(data.size()));
            }
            return data;
        }
        case FieldType::HexBytes:
            return fields.bytes(spec.name).toHex().toUpper();
        case FieldType::HexWords: {
            QList<qint64> words = fields.words(spec.name);
            if (!fields.has(spec.name) && spec.count > 0) words = QList<qint64>(spec.count, 0);
            if (spec.count >= 0 && words.size() != spec.count) {
                return Error::invalidData(
                    QCoreApplication::translate("cambench::comm",
                                                "Field \"%1\" needs exactly %2 words, got %3.")
                        .arg(fieldName(spec))
                        .arg(spec.count)
                        .arg(words.size()));
            }
            QByteArray out;
            for (qint64 word : words) {
                Result<QByteArray> digits = encodeHex(spec, word, false);
                if (!digits) return digits.error();
                out.append(*digits);
            }
            return out;
        }
    }
    return Error::usage(
        QCoreApplication::translate("cambench::comm", "Field \"%1\" has an unknown type.")
            .arg(fieldName(spec)));
}

// Characters a fixed field takes, or -1 for a field that runs to the end.
int fixedLength(const FieldSpec& spec) {
    if (isRest(spec)) return -1;
    if (spec.type == FieldType::HexWords) return spec.width * spec.count;
    return spec.width;
}

Error malformed(const FieldSpec& spec, int offset, const QString& what) {
    return Error::communication(
        QCoreApplication::translate("cambench::comm",
                                    "Malformed data: field \"%1\" at offset %2 %3.")
            .arg(fieldName(spec))
            .arg(offset)
            .arg(what));
}

Result<QList<qint64>> decodeWords(const FieldSpec& spec, QByteArrayView data, int offset) {
    if (data.size() % spec.width != 0) {
        return malformed(
            spec, offset,
            QCoreApplication::translate("cambench::comm", "has %1 characters, not a multiple of %2")
                .arg(data.size())
                .arg(spec.width));
    }
    QList<qint64> words;
    for (qsizetype i = 0; i < data.size(); i += spec.width) {
        const auto word = parseHex(data.sliced(i, spec.width));
        if (!word)
            return malformed(spec, offset + int(i),
                             QCoreApplication::translate("cambench::comm", "is not hexadecimal"));
        words.append(qint64(*word));
    }
    return words;
}

// Stores one field's decoded value; `data` is exactly the field's characters.
Status decodeField(const FieldSpec& spec, QByteArrayView data, int offset, Fields& fields) {
    switch (spec.type) {
        case FieldType::Hex:
        case FieldType::SignedHex: {
            const auto value = parseHex(data);
            if (!value)
                return malformed(
                    spec, offset,
                    QCoreApplication::translate("cambench::comm", "is not hexadecimal"));
            fields.set(spec.name, spec.type == FieldType::SignedHex ? signExtend(*value, spec.width)
                                                                    : qint64(*value));
            return success();
        }
        case FieldType::Text:
        case FieldType::TextRest: {
            const qsizetype nul = data.indexOf('\0');
            fields.setBytes(spec.name, (nul < 0 ? data : data.first(nul)).toByteArray());
            return success();
        }
        case FieldType::Binary:
            fields.setBytes(spec.name, data.toByteArray());
            return success();
        case FieldType::HexBytes: {
            if (data.size() % 2 != 0)
                return malformed(
                    spec, offset,
                    QCoreApplication::translate("cambench::comm", "has an odd number of digits"));
            QByteArray bytes;
            for (qsizetype i = 0; i < data.size(); i += 2) {
                const auto byte = parseHex(data.sliced(i, 2));
                if (!byte)
                    return malformed(
                        spec, offset + int(i),
                        QCoreApplication::translate("cambench::comm", "is not hexadecimal"));
                bytes.append(char(*byte));
            }
            fields.setBytes(spec.name, bytes);
            return success();
        }
        case FieldType::HexWords: {
            Result<QList<qint64>> words = decodeWords(spec, data, offset);
            if (!words) return words.error();
            fields.setWords(spec.name, *words);
            return success();
        }
    }
    return Error::usage(
        QCoreApplication::translate("cambench::comm", "Field \"%1\" has an unknown type.")
            .arg(fieldName(spec)));
}

// A reply body without its name: "ERR" + 8 hex digits.
std::optional<qint32> deviceErrorCode(QByteArrayView rest) {
    if (rest.size() != kErr.size() + kErrorDigits || !rest.startsWith(kErr)) return std::nullopt;
    const auto code = parseHex(rest.sliced(kErr.size()));
    if (!code) return std::nullopt;
    return qint32(quint32(*code));
}

ReplyMatch matchReplyData(const CommandSpec& spec, QByteArrayView rest) {
    ReplyMatch match;
    if (const auto code = deviceErrorCode(rest)) {
        match.kind = ReplyMatch::DeviceError;
        match.errorCode = *code;
        return match;
    }
    switch (spec.replyKind) {
        case ReplyKind::Ok:
            if (rest == kOk || (spec.okOptional && rest.isEmpty())) {
                match.kind = ReplyMatch::Matches;
            } else {
                match.kind = ReplyMatch::Malformed;
                match.detail =
                    QCoreApplication::translate("cambench::comm",
                                                "%1: expected \"OK\", got \"%2\".")
                        .arg(commandName(spec),
                             QString::fromLatin1(rest.toByteArray().toPercentEncoding(" ")));
            }
            return match;
        case ReplyKind::Data: {
            Result<Fields> fields = decodeFields(spec.reply, rest);
            if (fields) {
                match.kind = ReplyMatch::Matches;
                match.fields = std::move(fields).value();
            } else {
                match.kind = ReplyMatch::Malformed;
                match.detail = commandName(spec) + QStringLiteral(": ") + fields.error().message;
            }
            return match;
        }
        case ReplyKind::None:
            break;
    }
    // A command without a reply cannot be answered; whatever came belongs to
    // something else.
    match.kind = ReplyMatch::Unrelated;
    return match;
}

}  // namespace

Result<QByteArray> encodeFields(const QList<FieldSpec>& specs, const Fields& fields) {
    QByteArray out;
    for (const FieldSpec& spec : specs) {
        Result<QByteArray> encoded = encodeField(spec, fields);
        if (!encoded) return encoded.error();
        out.append(*encoded);
    }
    return out;
}

Result<Fields> decodeFields(const QList<FieldSpec>& specs, QByteArrayView data) {
    Fields fields;
    qsizetype offset = 0;
    for (const FieldSpec& spec : specs) {
        const int length = fixedLength(spec);
        const qsizetype available = data.size() - offset;
        if (length >= 0 && available < length) {
            return malformed(
                spec, int(offset),
                QCoreApplication::translate("cambench::comm", "needs %1 characters, only %2 left")
                    .arg(length)
                    .arg(available));
        }
        const qsizetype take = length >= 0 ? length : available;
        const Status decoded = decodeField(spec, data.sliced(offset, take), int(offset), fields);
        if (!decoded) return decoded.error();
        offset += take;
    }
    if (offset != data.size()) {
        return Error::communication(
            QCoreApplication::translate(
                "cambench::comm", "Malformed data: %1 unexpected characters after the last field.")
                .arg(data.size() - offset));
    }
    return fields;
}

Result<QByteArray> encodeRequestBody(const CommandSpec& spec, const Fields& fields) {
    Result<QByteArray> data = encodeFields(spec.request, fields);
    if (!data) {
        Error error = data.error();
        error.message = QCoreApplication::translate("cambench::comm", "Cannot send %1: %2")
                            .arg(commandName(spec), error.message);
        return error;
    }
    return QByteArray(spec.name) + *data;
}

ReplyMatch matchReply(const CommandSpec& spec, const Frame& reply) {
    ReplyMatch match;
    if (reply.lead != kReply) return match;
    const QByteArrayView body(reply.body);

    if (body.startsWith('Z') && spec.name[0] != 'Z') {
        match.kind = ReplyMatch::NotUnderstood;
        const QByteArrayView date = body.sliced(1);
        const qsizetype nul = date.indexOf('\0');
        match.eprom = (nul < 0 ? date : date.first(nul)).toByteArray();
        return match;
    }

    // An alias may prefix the name (MPE/MPEE) and data may begin with letters
    // of the name, so every name that fits is tried; the first decodable wins.
    QList<QByteArrayView> names{QByteArrayView(spec.name)};
    for (const QByteArray& alias : spec.replyAliases) names.append(alias);
    for (QByteArrayView name : names) {
        if (!body.startsWith(name)) continue;
        ReplyMatch candidate = matchReplyData(spec, body.sliced(name.size()));
        if (candidate.kind != ReplyMatch::Malformed) return candidate;
        if (match.kind != ReplyMatch::Malformed) match = candidate;
    }
    if (match.kind == ReplyMatch::Malformed) qCDebug(commProtocolLog) << match.detail;
    return match;
}

Result<Fields> decodeRequestFields(const CommandSpec& spec, QByteArrayView body) {
    if (!body.startsWith(QByteArrayView(spec.name))) {
        return Error::communication(
            QCoreApplication::translate("cambench::comm", "The request does not start with %1.")
                .arg(commandName(spec)));
    }
    Result<Fields> fields = decodeFields(spec.request, body.sliced(qstrlen(spec.name)));
    if (!fields) {
        Error error = fields.error();
        error.message = commandName(spec) + QStringLiteral(": ") + error.message;
        return error;
    }
    return fields;
}

Result<QByteArray> encodeReplyBody(const CommandSpec& spec, const Fields& fields) {
    if (spec.replyKind != ReplyKind::Data) {
        return Error::usage(QCoreApplication::translate("cambench::comm", "%1 has no data reply.")
                                .arg(commandName(spec)));
    }
    Result<QByteArray> data = encodeFields(spec.reply, fields);
    if (!data) {
        Error error = data.error();
        error.message = QCoreApplication::translate("cambench::comm", "Cannot answer %1: %2")
                            .arg(commandName(spec), error.message);
        return error;
    }
    return QByteArray(spec.name) + *data;
}

QByteArray okReplyBody(const CommandSpec& spec) {
    return QByteArray(spec.name) + kOk.toByteArray();
}

QByteArray errorReplyBody(const CommandSpec& spec, qint32 code) {
    return QByteArray(spec.name) + kErr.toByteArray() + hexDigits(quint32(code), kErrorDigits);
}

QByteArray notUnderstoodBody(QByteArrayView epromDate) {
    QByteArray body("Z");
    body.append(epromDate);
    body.append('\0');
    return body;
}

}  // namespace cambench::comm
