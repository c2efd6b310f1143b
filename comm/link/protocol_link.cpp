#include "protocol_link.h"

#include "link_logging.h"
#include "traffic_mask.h"

#include "comm/protocol/device_errors.h"

#include <QDeadlineTimer>

#include <algorithm>

namespace cambench::comm {

namespace {

// The longest a cancel request or a deadline waits for the transport.
constexpr int kSliceMs = 50;

QString commandLabel(char kind, QByteArrayView name) {
    return QString(QChar(kind)) + QString::fromLatin1(name);
}

// A terminal request named by its first characters, for messages.
QString rawLabel(char kind, const QByteArray& body) {
    QByteArray shown = body.left(12);
    for (char& c : shown)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F) c = '.';
    return commandLabel(kind, shown) + (body.size() > shown.size() ? QStringLiteral("...") : QString());
}

QString eepromDateText(const QByteArray& eprom) {
    QByteArray date = eprom;
    const qsizetype nul = date.indexOf('\0');
    if (nul >= 0) date.truncate(nul);
    return QString::fromLatin1(date.trimmed());
}

}  // namespace

ProtocolLink::ProtocolLink(Transport& transport, LinkSettings settings)
    : m_transport(transport),
      m_settings(settings),
      m_decoder(std::make_unique<StreamDecoder>(settings.framing, QByteArray(1, kReply))) {}

Result<Fields> ProtocolLink::call(char kind, const char* name, const Fields& fields,
                                  int timeoutMs) {
    const CommandSpec* spec = findCommand(kind, name);
    if (!spec)
        return Error::usage(QStringLiteral("%1 is not a command of the catalogue")
                                .arg(commandLabel(kind, name)));
    return call(*spec, fields, timeoutMs);
}

Result<Fields> ProtocolLink::call(const CommandSpec& spec, const Fields& fields, int timeoutMs) {
    const QString label = commandLabel(spec.kind, spec.name);
    Result<QByteArray> body = encodeRequestBody(spec, fields);
    if (!body) return body.error();

    ReplyMatch match;
    const Judge judge = [&](const Frame& frame, QString& problem) {
        match = matchReply(spec, frame);
        switch (match.kind) {
        case ReplyMatch::Matches:
        case ReplyMatch::DeviceError:
        case ReplyMatch::NotUnderstood: return Verdict::Accept;
        case ReplyMatch::Malformed:
            problem = QStringLiteral("a malformed reply: %1").arg(match.detail);
            return Verdict::Retry;
        case ReplyMatch::Unrelated: break;
        }
        return Verdict::Ignore;
    };
    const bool expectReply = spec.replyKind != ReplyKind::None;
    const Result<Frame> reply = exchange(label, spec.kind, *body,
                                         timeoutFor(&spec, *body, timeoutMs), expectReply, judge);
    if (!reply) return reply.error();
    if (!expectReply) return Fields{};

    switch (match.kind) {
    case ReplyMatch::DeviceError:
        return Error::device(match.errorCode,
                             QStringLiteral("%1: the device reported error %2: %3")
                                 .arg(label)
                                 .arg(match.errorCode)
                                 .arg(deviceErrorText(match.errorCode)));
    case ReplyMatch::NotUnderstood:
        return Error{ErrorKind::NotUnderstood,
                     QStringLiteral("%1: the device does not know this command (firmware dated "
                                    "%2); it needs a newer firmware for it")
                         .arg(label, eepromDateText(match.eprom)),
                     0};
    default: return match.fields;
    }
}

Result<QByteArray> ProtocolLink::raw(char kind, const QByteArray& body, int timeoutMs) {
    if (kind != kQuery && kind != kCommand)
        return Error::usage(
            QStringLiteral("a request starts with '?' or '!', not '%1'").arg(QChar(kind)));
    if (body.isEmpty())
        return Error::usage(QStringLiteral("an empty request: type the command letters after %1")
                                .arg(QChar(kind)));
    const CommandSpec* spec = matchRequest(kind, body);
    const bool expectReply = !spec || spec->replyKind != ReplyKind::None;
    const Result<Frame> reply =
        exchange(rawLabel(kind, body), kind, body, timeoutFor(spec, body, timeoutMs), expectReply,
                 [](const Frame&, QString&) { return Verdict::Accept; });
    if (!reply) return reply.error();
    return reply->body;
}

int ProtocolLink::timeoutFor(const CommandSpec* spec, const QByteArray& body,
                             int timeoutMs) const {
    if (timeoutMs > 0) return timeoutMs;
    // !EE erases the EEPROM, and takes long, only for block 0000.
    const bool eepromWrite = spec && spec->kind == kCommand && qstrcmp(spec->name, "EE") == 0;
    const bool isLong = eepromWrite ? body.startsWith("EE0000")
                                    : (spec && spec->timeout == TimeoutClass::Long);
    return isLong ? m_settings.longTimeoutMs : m_settings.timeoutMs;
}

Result<Frame> ProtocolLink::exchange(const QString& label, char kind, const QByteArray& body,
                                     int timeoutMs, bool expectReply, const Judge& judge) {
    ++m_stats.requests;
    m_lastAttempts = 0;
    m_lastHeardDevice = false;
    if (cancelled()) return Error::cancelled();
    dropStaleInput();

    Frame request{kind, body, std::nullopt, true};
    if (m_settings.framing == Framing::Multiuser) {
        const int device = std::clamp(m_settings.device, 0, 63);
        const int block = m_nextBlock[device];
        m_nextBlock[device] = (block + 1) % 64;
        request.address = MultiuserAddress{std::clamp(m_settings.pcNumber, 0, 63), device, block};
    }
    const QByteArray wire = encodeFrame(request);

    const int attempts = 1 + std::max(0, m_settings.retries);
    QString problem;
    for (int attempt = 1; attempt <= attempts; ++attempt) {
        if (cancelled()) return Error::cancelled();
        m_lastAttempts = attempt;
        if (attempt > 1) {
            ++m_stats.retries;
            qCDebug(commLinkLog) << "retrying" << label << "attempt" << attempt << "after"
                                 << problem;
            report(m_undecoded, false);
            m_undecoded.clear();
            m_transport.discardInput();
            m_decoder->reset();
        }
        report(wire, true);
        const Status sent = m_transport.write(wire);
        if (!sent) return sent.error();
        m_stats.bytesSent += wire.size();
        if (!expectReply) return Frame{};

        problem.clear();
        Result<std::optional<Frame>> reply = awaitReply(request.address, timeoutMs, judge, problem);
        if (!reply) return reply.error();
        if (reply->has_value()) return std::move(**reply);
    }
    const QString message = noReplyMessage(label, attempts, timeoutMs, problem);
    qCWarning(commLinkLog) << message;
    return Error::communication(message);
}

Result<std::optional<Frame>> ProtocolLink::awaitReply(
    const std::optional<MultiuserAddress>& request, int timeoutMs, const Judge& judge,
    QString& problem) {
    QDeadlineTimer deadline(timeoutMs);
    for (;;) {
        if (cancelled()) return Error::cancelled();
        const int slice = int(std::min<qint64>(kSliceMs, deadline.remainingTime()));
        Result<QByteArray> chunk = m_transport.read(slice);
        if (!chunk) {
            report(m_undecoded, false);
            m_undecoded.clear();
            return chunk.error();
        }
        if (!chunk->isEmpty()) {
            m_lastHeardDevice = true;
            m_stats.bytesReceived += chunk->size();
            m_undecoded += *chunk;
            const QList<DecodeEvent> events = m_decoder->feed(*chunk);
            m_undecoded = m_undecoded.right(m_decoder->pendingBytes());
            for (const DecodeEvent& event : events) {
                report(event.raw, false);
                switch (judgeFrame(event, request, judge, problem)) {
                case Verdict::Accept: return std::optional<Frame>(event.frame);
                case Verdict::Retry: return std::optional<Frame>();
                case Verdict::Ignore: break;
                }
            }
        }
        if (deadline.hasExpired()) {
            if (problem.isEmpty())
                problem = m_undecoded.isEmpty() ? QStringLiteral("no reply")
                                                : QStringLiteral("an incomplete reply");
            return std::optional<Frame>();
        }
    }
}

ProtocolLink::Verdict ProtocolLink::judgeFrame(const DecodeEvent& event,
                                               const std::optional<MultiuserAddress>& request,
                                               const Judge& judge, QString& problem) {
    // In Multiuser framing only a frame from the device we asked, to us, with
    // our block number is ours; the header is outside the checksum, so even a
    // damaged frame is only ours if its header says so.
    const auto isOurs = [&](const Frame& frame) {
        if (!request) return true;
        return frame.address && frame.address->source == request->destination &&
               frame.address->destination == request->source &&
               frame.address->block == request->block;
    };
    switch (event.kind) {
    case DecodeEvent::FrameOk:
        if (!isOurs(event.frame)) {
            qCDebug(commLinkLog) << "ignoring a frame for another device or block"
                                 << event.raw.toHex(' ');
            return Verdict::Ignore;
        }
        if (const Verdict verdict = judge(event.frame, problem); verdict != Verdict::Retry)
            return verdict;
        ++m_stats.badFrames;
        return Verdict::Retry;
    case DecodeEvent::BadChecksum:
        if (!isOurs(event.frame)) return Verdict::Ignore;
        ++m_stats.badFrames;
        problem = QStringLiteral("a reply with a wrong checksum");
        return Verdict::Retry;
    case DecodeEvent::Oversized:
        ++m_stats.badFrames;
        problem = QStringLiteral("an oversized reply");
        return Verdict::Retry;
    case DecodeEvent::Garbage:
        qCDebug(commLinkLog) << "skipped bytes outside a frame:" << event.raw.toHex(' ');
        return Verdict::Ignore;
    }
    return Verdict::Ignore;
}

QString ProtocolLink::noReplyMessage(const QString& label, int attempts, int timeoutMs,
                                     const QString& problem) const {
    const bool multiuser = m_settings.framing == Framing::Multiuser;
    const QString from =
        multiuser ? QStringLiteral(" from device %1").arg(m_settings.device) : QString();
    const QString what = problem == QLatin1String("no reply")
                             ? QStringLiteral("no reply")
                             : QStringLiteral("no valid reply (last: %1)").arg(problem);
    const QString check =
        multiuser ? QStringLiteral("check the cable, the baud rate, that the device speaks the "
                                   "Multiuser protocol and the device number")
                  : QStringLiteral("check the cable, the baud rate and that the device speaks "
                                   "the Standard protocol");
    return QStringLiteral("%1%2 to %3 on %4 after %5 attempts of %6 ms; %7")
        .arg(what, from, label, m_transport.description())
        .arg(attempts)
        .arg(timeoutMs)
        .arg(check);
}

void ProtocolLink::report(const QByteArray& bytes, bool outgoing) {
    if (!m_sink || bytes.isEmpty()) return;
    m_sink(TrafficEntry{QDateTime::currentDateTime(), outgoing, maskSecrets(bytes, outgoing)});
}

void ProtocolLink::dropStaleInput() {
    report(m_undecoded, false);
    m_undecoded.clear();
    m_decoder->reset();
    // A late answer to an earlier request must not pass for the next one's.
    const Result<QByteArray> stale = m_transport.read(0);
    if (stale && !stale->isEmpty()) {
        m_stats.bytesReceived += stale->size();
        qCDebug(commLinkLog) << "dropping" << stale->size() << "stale bytes";
        report(*stale, false);
    }
}

}  // namespace cambench::comm
