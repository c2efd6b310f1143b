#include "ascii_backend.h"

#include <QCoreApplication>

#include "traffic_mask.h"

namespace cambench::comm {

namespace {

// Header (Multiuser), lead, checksum, CR LF around a body.
constexpr int kHeaderBytes = 3;
constexpr int kFrameOverhead = 1 + 2 + 2;

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

BackendStep AsciiBackend::feed(QByteArrayView bytes, qint64) {
    BackendStep step;
    m_undecoded += bytes;
    const QList<DecodeEvent> events = m_decoder.feed(bytes);
    m_undecoded = m_undecoded.right(m_decoder.pendingBytes());
    for (const DecodeEvent& event : events) {
        Incoming in;
        in.wire = event.raw;
        switch (event.kind) {
            case DecodeEvent::FrameOk:
                if (isOurs(event.frame)) {
                    in.kind = Incoming::Message;
                    in.message = event.frame.lead + event.frame.body;
                } else {
                    in.kind = Incoming::Foreign;
                }
                break;
            case DecodeEvent::BadChecksum:
                in.kind = isOurs(event.frame) ? Incoming::Damaged : Incoming::Foreign;
                in.detail =
                    QCoreApplication::translate("cambench::comm", "a reply with a wrong checksum");
                break;
            case DecodeEvent::Oversized:
                in.kind = Incoming::Damaged;
                in.detail = QCoreApplication::translate("cambench::comm", "an oversized reply");
                break;
            case DecodeEvent::Garbage:
                in.kind = Incoming::Garbage;
                in.detail = event.detail;
                break;
        }
        step.incoming.append(in);
    }
    return step;
}

QByteArray AsciiBackend::resetInput() {
    m_decoder.reset();
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
    return maskSecrets(wire, outgoing);
}

}  // namespace cambench::comm
