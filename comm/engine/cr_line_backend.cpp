#include "cr_line_backend.h"

namespace cambench::comm {

std::optional<QByteArray> takeCrLine(QByteArray& buffer) {
    const qsizetype end = buffer.indexOf('\r');
    if (end < 0) return std::nullopt;
    QByteArray line = buffer.left(end);
    buffer.remove(0, end + 1);
    line.replace('\n', QByteArray());
    return line;
}

BackendStep CrLineBackend::startAttempt(const Request& request, int, qint64) {
    BackendStep step;
    step.write = requestLine(request);
    step.sent = true;
    return step;
}

BackendStep CrLineBackend::feed(QByteArrayView bytes, qint64) {
    BackendStep step;
    m_buffer.append(bytes.toByteArray());
    QByteArray before = m_buffer;
    while (const std::optional<QByteArray> line = takeCrLine(m_buffer)) {
        Incoming in;
        in.message = *line;
        in.wire = before.left(before.size() - m_buffer.size());
        before = m_buffer;
        step.incoming << in;
    }
    return step;
}

QByteArray CrLineBackend::resetInput() {
    return std::exchange(m_buffer, {});
}

}  // namespace cambench::comm
