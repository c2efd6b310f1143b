#include "stream_decoder.h"

#include <QCoreApplication>

#include "protocol_log.h"

namespace cambench::comm {

namespace {

constexpr int kHeaderBytes = 3;

int hexValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

// Manual 4.3.1: "!C0" travels without a checksum even while checksums are on,
// and the device acknowledges it with ":C0OK" without one.
bool isUncheckedC0(char lead, const QByteArray& body) {
    return (lead == kCommand && body == "C0") || (lead == kReply && body == "C0OK");
}

// Multiuser header byte i (0..2) lies in 0x40+0x40*i .. 0x7F+0x40*i.
bool isHeaderByte(int index, char c) {
    const int low = 0x40 + 0x40 * index;
    const int value = quint8(c);
    return value >= low && value <= low + 0x3F;
}

}  // namespace

StreamDecoder::StreamDecoder(Framing framing, QByteArray acceptLeads)
    : m_framing(framing), m_acceptLeads(std::move(acceptLeads)) {}

QList<DecodeEvent> StreamDecoder::feed(QByteArrayView bytes) {
    QList<DecodeEvent> events;
    for (char c : bytes) {
        switch (m_state) {
            case State::Hunt:
                huntByte(c, events);
                break;
            case State::Body:
                bodyByte(c, events);
                break;
            case State::Discard:
                discardByte(c, events);
                break;
        }
    }
    // Garbage is reported once per feed so that a log shows it near the time
    // it arrived; bytes that may still become a frame stay in m_buffer.
    flushGarbage(events);
    return events;
}

void StreamDecoder::reset() {
    m_buffer.clear();
    m_body.clear();
    m_garbage.clear();
    m_garbageReason.clear();
    m_escaped = false;
    m_crSeen = false;
    m_state = State::Hunt;
}

bool StreamDecoder::isFrameStartPrefix(QByteArrayView bytes) const {
    const int header = m_framing == Framing::Multiuser ? kHeaderBytes : 0;
    for (int i = 0; i < bytes.size() && i <= header; ++i) {
        const bool fits = i < header ? isHeaderByte(i, bytes[i]) : m_acceptLeads.contains(bytes[i]);
        if (!fits) return false;
    }
    return true;
}

void StreamDecoder::huntByte(char c, QList<DecodeEvent>& events) {
    m_buffer.append(c);
    // Drop leading bytes until what is held could still begin a frame.
    while (!m_buffer.isEmpty() && !isFrameStartPrefix(m_buffer)) {
        addGarbage(m_buffer.first(1),
                   QCoreApplication::translate("cambench::comm", "bytes outside any frame"),
                   events);
        m_buffer.remove(0, 1);
    }
    const int startLength = m_framing == Framing::Multiuser ? kHeaderBytes + 1 : 1;
    if (m_buffer.size() == startLength) {
        flushGarbage(events);
        startBody();
    }
}

void StreamDecoder::startBody() {
    m_state = State::Body;
    m_body.clear();
    m_escaped = false;
    m_crSeen = false;
}

void StreamDecoder::bodyByte(char c, QList<DecodeEvent>& events) {
    if (m_crSeen) {
        if (c == kLf) {
            m_buffer.append(c);
            completeFrame(events);
            return;
        }
        // Inside a frame every CR is escaped, so a bare CR was meant to end
        // it: the LF got lost. The byte after the CR may start a new frame.
        addGarbage(m_buffer,
                   QCoreApplication::translate("cambench::comm", "a frame ended by CR without LF"),
                   events);
        m_buffer.clear();
        m_state = State::Hunt;
        huntByte(c, events);
        return;
    }
    m_buffer.append(c);
    if (m_escaped) {
        m_body.append(c);
        m_escaped = false;
    } else if (c == kEsc) {
        m_escaped = true;
    } else if (c == kCr) {
        m_crSeen = true;
    } else {
        m_body.append(c);
    }
    if (m_buffer.size() >= kMaxFrameBytes) {
        DecodeEvent event;
        event.kind = DecodeEvent::Oversized;
        event.raw = m_buffer;
        event.detail = QCoreApplication::translate(
                           "cambench::comm", "No frame end within %1 bytes; the frame was dropped.")
                           .arg(kMaxFrameBytes);
        qCWarning(commProtocolLog) << event.detail;
        flushGarbage(events);
        events.append(event);
        m_buffer.clear();
        m_body.clear();
        m_state = State::Discard;  // m_escaped/m_crSeen carry over to find the real end
    }
}

void StreamDecoder::discardByte(char c, QList<DecodeEvent>& events) {
    addGarbage(QByteArrayView(&c, 1),
               QCoreApplication::translate("cambench::comm", "the rest of an oversized frame"),
               events);
    if (m_escaped) {
        m_escaped = false;
        return;
    }
    if (m_crSeen && c == kLf) {
        m_crSeen = false;
        flushGarbage(events);
        m_state = State::Hunt;
        return;
    }
    m_crSeen = c == kCr;
    m_escaped = c == kEsc;
}

void StreamDecoder::completeFrame(QList<DecodeEvent>& events) {
    const int header = m_framing == Framing::Multiuser ? kHeaderBytes : 0;
    DecodeEvent event;
    event.raw = m_buffer;
    Frame& frame = event.frame;
    frame.lead = m_buffer.at(header);
    if (header) {
        frame.address = MultiuserAddress{quint8(m_buffer[0]) - 0x40, quint8(m_buffer[1]) - 0x80,
                                         quint8(m_buffer[2]) - 0xC0};
    }

    if (!m_checksumEnabled || isUncheckedC0(frame.lead, m_body)) {
        frame.body = m_body;
        frame.hasChecksum = false;
        event.kind = DecodeEvent::FrameOk;
    } else if (m_body.size() < 2 || hexValue(m_body.at(m_body.size() - 2)) < 0 ||
               hexValue(m_body.back()) < 0) {
        frame.body = m_body;
        frame.hasChecksum = false;
        event.kind = DecodeEvent::BadChecksum;
        event.detail =
            QCoreApplication::translate("cambench::comm", "The frame has no checksum characters.");
    } else {
        frame.body = m_body.chopped(2);
        frame.hasChecksum = true;
        const int received = hexValue(m_body.at(m_body.size() - 2)) * 16 + hexValue(m_body.back());
        const quint8 expected = checksum(frame.lead, frame.body);
        if (received == expected) {
            event.kind = DecodeEvent::FrameOk;
        } else {
            event.kind = DecodeEvent::BadChecksum;
            event.detail =
                QCoreApplication::translate("cambench::comm", "Checksum %1 received, %2 expected.")
                    .arg(QString::fromLatin1(m_body.right(2)),
                         QString::fromLatin1(checksumText(expected)));
        }
    }
    if (event.kind == DecodeEvent::BadChecksum) qCDebug(commProtocolLog) << event.detail;

    events.append(event);
    m_buffer.clear();
    m_body.clear();
    m_escaped = false;
    m_crSeen = false;
    m_state = State::Hunt;
}

void StreamDecoder::addGarbage(QByteArrayView bytes, const QString& reason,
                               QList<DecodeEvent>& events) {
    if (!m_garbage.isEmpty() && reason != m_garbageReason) flushGarbage(events);
    m_garbageReason = reason;
    m_garbage.append(bytes);
    if (m_garbage.size() >= kMaxFrameBytes) flushGarbage(events);
}

void StreamDecoder::flushGarbage(QList<DecodeEvent>& events) {
    if (m_garbage.isEmpty()) return;
    DecodeEvent event;
    event.kind = DecodeEvent::Garbage;
    event.raw = m_garbage;
    event.detail = QCoreApplication::translate("cambench::comm", "Skipped %1 bytes: %2.")
                       .arg(m_garbage.size())
                       .arg(m_garbageReason);
    qCDebug(commProtocolLog) << event.detail;
    events.append(event);
    m_garbage.clear();
}

}  // namespace cambench::comm
