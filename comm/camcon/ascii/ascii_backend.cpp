#include "ascii_backend.h"

#include <QCoreApplication>

#include "traffic_mask.h"

namespace cambench::comm {

namespace {

// Header (Multiuser), lead, checksum, CR LF around a body.
constexpr int kHeaderBytes = 3;
constexpr int kFrameOverhead = 1 + 2 + 2;

// Requests whose frames carry secrets (notes 4 and 6): the user numbers of
// !USER and ?USER, the EEPROM blocks of !EE and ?EE, which hold them too.
bool carriesSecrets(const QByteArray& message) {
    const QByteArrayView body = QByteArrayView(message).sliced(qMin<qsizetype>(1, message.size()));
    return body.startsWith("USER") || body.startsWith("EE");
}

}  // namespace

AsciiBackend::AsciiBackend(Framing framing, int device, int pcNumber)
    : m_framing(framing),
      m_device(clampNumber(device)),
      m_pcNumber(clampNumber(pcNumber)),
      m_decoder(framing, QByteArray(1, kReply)) {}

void AsciiBackend::setDevice(int device) {
    m_device = clampNumber(device);
}

QString AsciiBackend::describe() const {
    if (m_framing == Framing::Multiuser)
        return QCoreApplication::translate("cambench::comm", "device %1").arg(m_device);
    return QCoreApplication::translate("cambench::comm", "the device");
}

QString AsciiBackend::checkHint() const {
    if (m_framing == Framing::Multiuser)
        return QCoreApplication::translate(
            "cambench::comm",
            "check the cable, the baud rate, that the device speaks the "
            "Multiuser protocol and the device number");
    return QCoreApplication::translate(
        "cambench::comm",
        "check the cable, the baud rate and that the device speaks the "
        "Standard protocol");
}

void AsciiBackend::beginRequest(const Request& request) {
    Frame frame{request.message.isEmpty() ? kQuery : request.message.at(0), request.message.mid(1),
                std::nullopt, true};
    m_address.reset();
    if (m_framing == Framing::Multiuser) {
        // A new request takes the next block number; its retries reuse it,
        // so that the device answers a repeat without executing it again.
        const int block = m_nextBlock[m_device];
        m_nextBlock[m_device] = (block + 1) % 64;
        m_address = MultiuserAddress{m_pcNumber, m_device, block};
        frame.address = m_address;
    }
    m_wire = encodeFrame(frame);
    m_secretRequest = carriesSecrets(request.message);
}

BackendStep AsciiBackend::startAttempt(const Request&, int, qint64) {
    BackendStep step;
    step.write = m_wire;
    step.sent = true;
    return step;
}

bool AsciiBackend::isOurs(const Frame& frame) const {
    // In Multiuser framing only a frame from the device we asked, to us,
    // with our block number is ours; the header is outside the checksum, so
    // even a damaged frame is only ours if its header says so.
    if (!m_address) return true;
    return frame.address && frame.address->source == m_address->destination &&
           frame.address->destination == m_address->source &&
           frame.address->block == m_address->block;
}

int AsciiBackend::headerMatches(QByteArrayView wire) const {
    if (!m_address || wire.size() < kHeaderBytes) return 0;
    const char expected[kHeaderBytes] = {char(0x40 + m_address->destination),
                                         char(0x80 + m_address->source),
                                         char(0xC0 + m_address->block)};
    int matches = 0;
    for (int i = 0; i < kHeaderBytes; ++i) matches += wire[i] == expected[i] ? 1 : 0;
    return matches;
}

bool AsciiBackend::looksLikeOurReply(QByteArrayView line) const {
    // A reply whose lead (or a header byte) was hit still shows two of our
    // three header bytes (Multiuser) or, after its first byte, the first two
    // letters of our command (Standard): noise and other stations' lines
    // do not.
    if (m_wire.isEmpty()) return false;
    if (m_framing == Framing::Multiuser) return headerMatches(line) >= kHeaderBytes - 1;
    const QByteArrayView name =
        QByteArrayView(m_wire).sliced(1, qMin<qsizetype>(2, m_wire.size() - 1));
    return line.size() > name.size() && line.sliced(1).startsWith(name);
}

bool AsciiBackend::isEcho(QByteArrayView line) const {
    // An RS485 adapter may echo what the PC sends: our own request, whole or
    // in part, is not a damaged reply.
    return !line.isEmpty() && QByteArrayView(m_wire).contains(line);
}

Incoming AsciiBackend::classify(const DecodeEvent& event) {
    Incoming in;
    in.wire = event.raw;
    switch (event.kind) {
        case DecodeEvent::FrameOk: {
            const std::optional<MultiuserAddress>& address = event.frame.address;
            if (address && address->destination == m_pcNumber) {
                // Intact and for us: the header names who answered which block.
                in.source = address->source;
                in.sequence = address->block;
            }
            // A frame from another device or under another block is never
            // the answer (another device's late answer, an old block), even
            // if a header byte of it was hit and it was ours.
            if (isOurs(event.frame)) {
                in.kind = Incoming::Message;
                in.message = event.frame.lead + event.frame.body;
            } else {
                in.kind = Incoming::Foreign;
            }
            return in;
        }
        case DecodeEvent::BadChecksum:
            in.kind = isOurs(event.frame) ? Incoming::Damaged : Incoming::Foreign;
            in.detail =
                QCoreApplication::translate("cambench::comm", "a reply with a wrong checksum");
            return in;
        case DecodeEvent::Oversized:
            in.kind = Incoming::Damaged;
            in.detail = QCoreApplication::translate("cambench::comm", "an oversized reply");
            return in;
        case DecodeEvent::Garbage:
            return classifyGarbage(event);
    }
    return in;
}

Incoming AsciiBackend::classifyGarbage(const DecodeEvent& event) {
    Incoming in;
    in.wire = event.raw;
    in.kind = Incoming::Garbage;
    in.detail = event.detail;
    m_garbageLine += event.raw;
    if (!event.raw.contains(kCr) && !event.raw.contains(kLf)) return in;
    // A line without a frame in it, ended by CR or LF: a reply whose lead
    // (or, in Multiuser, a header byte) was hit, unless it is our echo.
    const QByteArray line = std::exchange(m_garbageLine, QByteArray());
    if (looksLikeOurReply(line) && !isEcho(line)) {
        in.kind = Incoming::Damaged;
        in.detail = QCoreApplication::translate("cambench::comm", "a reply without a frame start");
    }
    return in;
}

void AsciiBackend::armGapTimer(qint64 nowMs) {
    // Unfinished input - part of a frame, or of a line outside frames that
    // is not our echo - either continues within the gap or has broken off.
    const bool unfinished =
        m_decoder.pendingBytes() > 0 || (!m_garbageLine.isEmpty() && !isEcho(m_garbageLine));
    m_gapDeadline = unfinished ? nowMs + m_gapMs : -1;
}

BackendStep AsciiBackend::feed(QByteArrayView bytes, qint64 nowMs) {
    BackendStep step;
    m_undecoded += bytes;
    const QList<DecodeEvent> events = m_decoder.feed(bytes);
    m_undecoded = m_undecoded.right(m_decoder.pendingBytes());
    for (const DecodeEvent& event : events) step.incoming.append(classify(event));
    armGapTimer(nowMs);
    return step;
}

BackendStep AsciiBackend::poll(qint64 nowMs) {
    BackendStep step;
    if (m_gapDeadline < 0 || nowMs < m_gapDeadline) return step;
    m_gapDeadline = -1;
    Incoming in;
    in.wire = std::exchange(m_undecoded, QByteArray());
    const QByteArray line = std::exchange(m_garbageLine, QByteArray());
    m_decoder.reset();
    // A partial frame has our lead: in Standard framing that is enough, in
    // Multiuser its header must be ours; a partial line outside frames must
    // show more of our reply.
    bool ours = false;
    if (in.wire.isEmpty()) {
        ours = looksLikeOurReply(line);
    } else {
        ours = m_framing == Framing::Standard ? !m_wire.isEmpty()
                                              : headerMatches(in.wire) >= kHeaderBytes - 1;
    }
    in.kind = ours ? Incoming::Damaged : Incoming::Garbage;
    in.detail =
        QCoreApplication::translate("cambench::comm", "a reply that broke off before its end");
    // The garbage was logged when it came; only the partial frame is new.
    step.incoming.append(in);
    return step;
}

QByteArray AsciiBackend::resetInput() {
    m_decoder.reset();
    m_garbageLine.clear();
    m_gapDeadline = -1;
    QByteArray pending;
    pending.swap(m_undecoded);
    return pending;
}

qint64 AsciiBackend::requestWireBytes(const Request& request) const {
    const qint64 header = m_framing == Framing::Multiuser ? kHeaderBytes : 0;
    return header + kFrameOverhead + escapeBody(request.message.mid(1)).size();
}

qint64 AsciiBackend::replyWireBytes(const Request& request) const {
    // longestReplyBytes counts the lead and the body with its escapes.
    const qint64 header = m_framing == Framing::Multiuser ? kHeaderBytes : 0;
    return header + kFrameOverhead - 1 + qint64(request.longestReplyBytes);
}

QByteArray AsciiBackend::maskForLog(const QByteArray& wire, bool outgoing) const {
    if (outgoing || !m_secretRequest) return maskSecrets(wire, outgoing);
    // While a request that carries secrets waits, a damaged reply or bytes
    // outside frames may hold them in clear where no field can be found:
    // only a well-formed reply to it is shown, with its secrets masked.
    return isSecretReply(wire) ? maskSecrets(wire, false) : maskAll(wire);
}

}  // namespace cambench::comm
