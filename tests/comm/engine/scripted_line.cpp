#include "scripted_line.h"

#include <algorithm>

namespace cambench::comm::test {

void FakeBackend::beginRequest(const Request& request) {
    ++m_sequence;
    m_wire = request.message + '#' + QByteArray::number(m_sequence) + '\n';
}

BackendStep FakeBackend::startAttempt(const Request&, int, qint64) {
    BackendStep step;
    step.write = m_wire;
    step.sent = true;
    return step;
}

BackendStep FakeBackend::feed(QByteArrayView bytes, qint64) {
    BackendStep step;
    m_pending += bytes;
    for (qsizetype end = m_pending.indexOf('\n'); end >= 0; end = m_pending.indexOf('\n')) {
        Incoming in;
        in.wire = m_pending.left(end + 1);
        const QByteArray line = m_pending.left(end);
        m_pending.remove(0, end + 1);
        if (line.startsWith('!')) {
            in.kind = Incoming::Damaged;
            in.detail = QStringLiteral("a damaged line");
        } else if (line.startsWith('~')) {
            in.kind = Incoming::Foreign;
        } else {
            in.kind = Incoming::Message;
            in.message = line;
        }
        step.incoming.append(in);
    }
    return step;
}

QByteArray FakeBackend::resetInput() {
    return std::exchange(m_pending, QByteArray());
}

qint64 FakeBackend::requestWireBytes(const Request& request) const {
    return request.message.size() + 3;  // '#', one digit, '\n'
}

qint64 FakeBackend::replyWireBytes(const Request& request) const {
    return request.longestReplyBytes + 1;
}

Status ScriptedLine::write(const QByteArray& bytes) {
    const int index = int(m_writes.size());
    m_writes.append({m_clock.nowMs, bytes});
    if (!m_script) return success();
    for (const ScriptedReply& reply : m_script(bytes, index))
        schedule(m_clock.nowMs + reply.afterMs, reply.bytes);
    return success();
}

void ScriptedLine::schedule(qint64 atMs, const QByteArray& bytes) {
    const auto later = std::upper_bound(
        m_pending.begin(), m_pending.end(), atMs,
        [](qint64 time, const std::pair<qint64, QByteArray>& item) { return time < item.first; });
    m_pending.insert(later, {atMs, bytes});
}

QByteArray ScriptedLine::takeDue() {
    QByteArray due;
    while (!m_pending.isEmpty() && m_pending.first().first <= m_clock.nowMs)
        due += m_pending.takeFirst().second;
    return due;
}

Result<QByteArray> ScriptedLine::read(int timeoutMs) {
    QByteArray due = takeDue();
    if (!due.isEmpty()) return due;
    const qint64 until = m_clock.nowMs + std::max(0, timeoutMs);
    const qint64 next = m_pending.isEmpty() ? until : std::min(until, m_pending.first().first);
    m_clock.nowMs = std::max(m_clock.nowMs, next);
    return takeDue();
}

}  // namespace cambench::comm::test
