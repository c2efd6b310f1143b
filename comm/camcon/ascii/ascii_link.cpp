#include "ascii_link.h"

#include <QCoreApplication>

#include "device_errors.h"

#include <algorithm>
#include <cstring>

namespace cambench::comm {

namespace {

// The most data a variable-length reply field carries, for the timeout.
constexpr int kLongestBinaryBytes = 15 * 6;  // an EEPROM block (notes 6: nibble x 6)
constexpr int kLongestRestChars = 128;       // texts and status tables
constexpr int kLongestWordList = 64;
// ":" name "ERR" + 8 hex, and ":Z" + EPROM date.
constexpr int kErrorReplyChars = 3 + 8;
constexpr int kNotUnderstoodChars = 1 + 11;

QString commandLabel(char kind, QByteArrayView name) {
    return QString(QChar(kind)) + QString::fromLatin1(name);
}

// A terminal request named by its first characters, for messages.
QString rawLabel(char kind, const QByteArray& body) {
    QByteArray shown = body.left(12);
    for (char& c : shown)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F) c = '.';
    return commandLabel(kind, shown) +
           (body.size() > shown.size() ? QStringLiteral("...") : QString());
}

QString eepromDateText(const QByteArray& eprom) {
    QByteArray date = eprom;
    const qsizetype nul = date.indexOf('\0');
    if (nul >= 0) date.truncate(nul);
    return QString::fromLatin1(date.trimmed());
}

int fieldChars(const FieldSpec& field) {
    switch (field.type) {
        case FieldType::Hex:
        case FieldType::SignedHex:
        case FieldType::Text:
            return field.width;
        case FieldType::TextRest:
        case FieldType::HexBytes:
            return kLongestRestChars;
        case FieldType::Binary:  // every byte may need an ESC
            return 2 * (field.width < 0 ? kLongestBinaryBytes : field.width);
        case FieldType::HexWords:
            return field.width * (field.count < 0 ? kLongestWordList : field.count);
    }
    return 0;
}

// The longest reply `spec` may get, lead and body, escapes included.
int longestReplyChars(const CommandSpec& spec) {
    int data = 0;
    if (spec.replyKind == ReplyKind::Ok) data = 2;
    for (const FieldSpec& field : spec.reply) data += fieldChars(field);
    const int name = int(std::strlen(spec.name));
    return 1 + std::max({name + data, name + kErrorReplyChars, kNotUnderstoodChars});
}

// "EE" and a block number: an !EE without data, which ends a restore.
constexpr int kEepromBlockHeader = 2 + 4;

// !EE takes long only for block 0000, which erases the EEPROM, and for the
// empty block that ends a restore and starts the device (notes 6).
bool isLong(const CommandSpec* spec, const QByteArray& body) {
    if (!spec) return false;
    const bool eepromWrite = spec->kind == kCommand && qstrcmp(spec->name, "EE") == 0;
    if (!eepromWrite) return spec->timeout == TimeoutClass::Long;
    return body.startsWith("EE0000") || body.size() == kEepromBlockHeader;
}

// A reply judged against `spec`: its answer, or a reply to something else -
// in Multiuser framing under our block number, the device's repeated answer
// to an earlier request, which it did not execute this one for.
Verdict judgeUnrelated(bool multiuser, QString& problem) {
    if (!multiuser) return Verdict::Ignore;
    problem = QCoreApplication::translate("cambench::comm",
                                          "the device repeated an answer to an earlier request");
    return Verdict::Resend;
}

}  // namespace

AsciiLink::AsciiLink(Transport& transport, AsciiSettings settings, LineTiming line)
    : AsciiLink(
          transport, settings, line,
          std::make_unique<AsciiBackend>(settings.framing, settings.device, settings.pcNumber)) {}

AsciiLink::AsciiLink(Transport& transport, AsciiSettings settings, LineTiming line,
                     std::unique_ptr<FramingBackend> backend)
    : m_settings(settings),
      m_line(line),
      m_backend(std::move(backend)),
      m_ascii(dynamic_cast<AsciiBackend*>(m_backend.get())),
      m_engine(transport, *m_backend) {
    applySettings();
}

void AsciiLink::applySettings() {
    EngineSettings engine;
    engine.line = m_line;
    engine.line.longWorkMs = m_settings.longTimeoutMs;
    engine.retries = m_settings.retries;
    engine.fixedTimeoutMs = m_settings.timeoutMs;
    m_engine.setSettings(engine);
}

void AsciiLink::setDevice(int device) {
    m_settings.device = AsciiBackend::clampNumber(device);
    m_backend->setDevice(device);
}

void AsciiLink::setTimeout(int ms) {
    m_settings.timeoutMs = ms;
    applySettings();
}

void AsciiLink::setRetries(int retries) {
    m_settings.retries = retries;
    applySettings();
}

void AsciiLink::setLineTiming(const LineTiming& line) {
    m_line = line;
    applySettings();
}

Result<Request> AsciiLink::makeRequest(const CommandSpec& spec, const Fields& fields, int timeoutMs,
                                       ReplyMatch* match) {
    Result<QByteArray> body = encodeRequestBody(spec, fields);
    if (!body) return body.error();
    Request request;
    request.label = commandLabel(spec.kind, spec.name);
    request.message = spec.kind + *body;
    request.longestReplyBytes = longestReplyChars(spec);
    request.timeout = isLong(&spec, *body) ? TimeoutClass::Long : TimeoutClass::Normal;
    request.retry = spec.retry;
    request.expectReply = spec.replyKind != ReplyKind::None;
    request.fixedTimeoutMs = timeoutMs;
    const bool multiuser = m_settings.framing == Framing::Multiuser;
    if (match) {
        request.judge = [&spec, match, multiuser](const QByteArray& reply, QString& problem) {
            const Frame frame{reply.isEmpty() ? kReply : reply.at(0), reply.mid(1), std::nullopt,
                              true};
            *match = matchReply(spec, frame);
            switch (match->kind) {
                case ReplyMatch::Matches:
                case ReplyMatch::DeviceError:
                case ReplyMatch::NotUnderstood:
                    return Verdict::Accept;
                case ReplyMatch::Malformed:
                    problem = QCoreApplication::translate("cambench::comm", "a malformed reply: %1")
                                  .arg(match->detail);
                    return Verdict::Retry;
                case ReplyMatch::Unrelated:
                    break;
            }
            return judgeUnrelated(multiuser, problem);
        };
    }
    if (request.timeout == TimeoutClass::Long && timeoutMs <= 0) {
        // A silent busy device does not answer ?ERR either; one that answers
        // it has lost the long command's answer.
        request.probe = []() {
            const CommandSpec* err = findCommand(kQuery, "ERR");
            Request probe;
            probe.label = QStringLiteral("?ERR");
            probe.message = QByteArray("?ERR");
            probe.longestReplyBytes = err ? longestReplyChars(*err) : 16;
            probe.judge = [err](const QByteArray& reply, QString&) {
                if (!err) return Verdict::Accept;
                const Frame frame{reply.isEmpty() ? kReply : reply.at(0), reply.mid(1),
                                  std::nullopt, true};
                return matchReply(*err, frame).kind == ReplyMatch::Unrelated ? Verdict::Ignore
                                                                             : Verdict::Accept;
            };
            return probe;
        };
    }
    return request;
}

Status AsciiLink::ensureBlockSync() {
    if (m_settings.framing != Framing::Multiuser || !m_settings.syncBlockNumbers) return success();
    const int device = m_settings.device;
    if (m_synced[device]) return success();
    m_synced[device] = true;
    // The device may have seen this run's first block number last (an
    // earlier run ended there): ?UNIT changes nothing and, answered, leaves
    // the device's last block number equal to ours; if the device repeats
    // an old answer instead, the engine resends it under the next number.
    const CommandSpec* unit = findCommand(kQuery, "UNIT");
    ReplyMatch match;
    Result<Request> request = makeRequest(*unit, {}, 0, &match);
    if (!request) return request.error();
    const Result<QByteArray> reply = m_engine.send(*request);
    if (!reply) {
        m_synced[device] = false;
        return reply.error();
    }
    return success();
}

Result<bool> AsciiLink::ping(int device, int block, int turnaroundMs) {
    setDevice(device);
    if (m_ascii) m_ascii->setNextBlock(device, block);
    const CommandSpec* unit = findCommand(kQuery, "UNIT");
    Result<Request> made = makeRequest(*unit, {}, m_settings.timeoutMs, nullptr);
    if (!made) return made.error();
    Request request = std::move(made).value();
    request.maxAttempts = 1;
    request.turnaroundMs = turnaroundMs;
    request.silenceExpected = true;
    // Any intact frame from the device to us under this block proves it,
    // even its repeated answer to an older request.
    request.judge = {};
    const Result<QByteArray> reply = m_engine.send(request);
    if (reply) {
        m_synced[m_settings.device] = true;
        return true;
    }
    if (reply.error().kind == ErrorKind::Communication) return false;
    return reply.error();
}

int AsciiLink::attemptTimeoutMs(const CommandSpec& spec, const Fields& fields) {
    Result<Request> request = makeRequest(spec, fields, 0, nullptr);
    return request ? m_engine.attemptTimeoutMs(*request) : 0;
}

Result<Fields> AsciiLink::call(char kind, const char* name, const Fields& fields, int timeoutMs) {
    const CommandSpec* spec = findCommand(kind, name);
    if (!spec)
        return Error::usage(
            QCoreApplication::translate("cambench::comm", "%1 is not a command of the catalogue")
                .arg(commandLabel(kind, name)));
    return call(*spec, fields, timeoutMs);
}

Result<Fields> AsciiLink::call(const CommandSpec& spec, const Fields& fields, int timeoutMs) {
    const bool isSync = spec.kind == kQuery && qstrcmp(spec.name, "UNIT") == 0;
    if (!isSync) {
        const Status synced = ensureBlockSync();
        if (!synced) return synced.error();
    } else {
        m_synced[m_settings.device] = true;
    }
    ReplyMatch match;
    Result<Request> request = makeRequest(spec, fields, timeoutMs, &match);
    if (!request) return request.error();
    const Result<QByteArray> reply = m_engine.send(*request);
    if (!reply) return reply.error();
    if (!request->expectReply) return Fields{};

    const QString label = request->label;
    switch (match.kind) {
        case ReplyMatch::DeviceError:
            return Error::device(match.errorCode,
                                 QCoreApplication::translate("cambench::comm",
                                                             "%1: the device reported error %2: %3")
                                     .arg(label)
                                     .arg(match.errorCode)
                                     .arg(deviceErrorText(match.errorCode)));
        case ReplyMatch::NotUnderstood:
            return Error{ErrorKind::NotUnderstood,
                         QCoreApplication::translate(
                             "cambench::comm",
                             "%1: the device does not know this command (firmware dated "
                             "%2); it needs a newer firmware for it")
                             .arg(label, eepromDateText(match.eprom)),
                         0};
        default:
            return match.fields;
    }
}

Result<QByteArray> AsciiLink::raw(char kind, const QByteArray& body, int timeoutMs) {
    if (kind != kQuery && kind != kCommand)
        return Error::usage(QCoreApplication::translate(
                                "cambench::comm", "a request starts with '?' or '!', not '%1'")
                                .arg(QChar(kind)));
    if (body.isEmpty())
        return Error::usage(
            QCoreApplication::translate("cambench::comm",
                                        "an empty request: type the command letters after %1")
                .arg(QChar(kind)));
    const Status synced = ensureBlockSync();
    if (!synced) return synced.error();
    const CommandSpec* spec = matchRequest(kind, body);
    Request request;
    request.label = rawLabel(kind, body);
    request.message = kind + body;
    request.longestReplyBytes = spec ? longestReplyChars(*spec) : kLongestRestChars;
    request.timeout = isLong(spec, body) ? TimeoutClass::Long : TimeoutClass::Normal;
    // A typed command is sent once in Standard framing: nobody checks after it.
    request.retry = spec ? spec->retry : RetryPolicy::Never;
    if (kind == kCommand && m_settings.framing == Framing::Standard && spec &&
        spec->retry != RetryPolicy::Idempotent)
        request.retry = RetryPolicy::Never;
    request.expectReply = !spec || spec->replyKind != ReplyKind::None;
    request.fixedTimeoutMs = timeoutMs;
    if (spec) {
        // A reply to another command is never the answer; anything this
        // command may get back (data, OK, an error, :Z, a malformed reply
        // to a provisional format) is shown to the person who typed it.
        const bool multiuser = m_settings.framing == Framing::Multiuser;
        request.judge = [spec, multiuser](const QByteArray& reply, QString& problem) {
            const Frame frame{reply.isEmpty() ? kReply : reply.at(0), reply.mid(1), std::nullopt,
                              true};
            if (matchReply(*spec, frame).kind != ReplyMatch::Unrelated) return Verdict::Accept;
            return judgeUnrelated(multiuser, problem);
        };
    }
    const Result<QByteArray> reply = m_engine.send(request);
    if (!reply) return reply.error();
    return reply->mid(1);
}

}  // namespace cambench::comm
