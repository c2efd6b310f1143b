#include "sim_pacer.h"

#include <algorithm>

namespace cambench::comm {

namespace {
constexpr qint64 kUsPerSecond = 1000000;
}  // namespace

int PacedReply::bytesDueAt(qint64 nowUs) const {
    if (nowUs < startUs) return 0;
    if (baud <= 0) return int(bytes.size());
    const qint64 due = (nowUs - startUs) * baud / (bitsPerByte * kUsPerSecond);
    return int(std::min<qint64>(due, bytes.size()));
}

qint64 PacedReply::dueUs(int count) const {
    if (baud <= 0) return startUs;
    // Round up so that bytesDueAt(dueUs(n)) >= n.
    const qint64 bitsUs = qint64(count) * bitsPerByte * kUsPerSecond;
    return startUs + (bitsUs + baud - 1) / baud;
}

SimPacer::SimPacer(int baud, bool throttle, int bitsPerByte)
    : m_baud(std::max(baud, 1)), m_throttle(throttle), m_bitsPerByte(std::max(bitsPerByte, 1)) {}

qint64 SimPacer::transferUs(qint64 bytes) const {
    if (!m_throttle) return 0;
    return (bytes * m_bitsPerByte * kUsPerSecond + m_baud - 1) / m_baud;
}

QList<PacedReply> SimPacer::schedule(qint64 sentUs, int requestBytes,
                                     const QList<SimOutput>& outputs) {
    const qint64 arrivedUs = std::max(sentUs, m_toDeviceFreeUs) + transferUs(requestBytes);
    m_toDeviceFreeUs = arrivedUs;
    QList<PacedReply> replies;
    for (const SimOutput& output : outputs) {
        PacedReply reply;
        reply.bytes = output.bytes;
        reply.baud = m_throttle ? m_baud : 0;
        reply.bitsPerByte = m_bitsPerByte;
        reply.startUs = std::max(arrivedUs + qint64(output.delayMs) * 1000, m_toPcFreeUs);
        m_toPcFreeUs = reply.endUs();
        replies.append(reply);
    }
    return replies;
}

QByteArray PacedQueue::takeDue(qint64 nowUs) {
    QByteArray out;
    while (!m_replies.isEmpty()) {
        const PacedReply& reply = m_replies.first();
        const int due = reply.bytesDueAt(nowUs);
        out += reply.bytes.mid(m_taken, due - m_taken);
        m_taken = std::max(m_taken, due);
        if (m_taken < reply.bytes.size()) break;
        m_replies.removeFirst();
        m_taken = 0;
    }
    return out;
}

std::optional<qint64> PacedQueue::nextDueUs() const {
    if (m_replies.isEmpty()) return std::nullopt;
    return m_replies.first().dueUs(m_taken + 1);
}

void PacedQueue::clear() {
    m_replies.clear();
    m_taken = 0;
}

}  // namespace cambench::comm
