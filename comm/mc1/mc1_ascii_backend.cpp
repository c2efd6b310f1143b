#include "mc1_ascii_backend.h"

#include "mc1_ascii.h"

#include <QCoreApplication>

namespace cambench::comm {

QString Mc1AsciiBackend::describe() const {
    return QCoreApplication::translate("cambench::comm", "the MC100 (ASCII protocol)");
}

QString Mc1AsciiBackend::checkHint() const {
    return QCoreApplication::translate(
        "cambench::comm",
        "check the cable (RxD/TxD crossed), 9600 baud, and that the MC100 speaks ASCII (a "
        "controller set to the binary protocol answers only that: connect with mc1)");
}

BackendStep Mc1AsciiBackend::startAttempt(const Request& request, int, qint64) {
    BackendStep step;
    step.write = request.message;
    step.sent = true;
    return step;
}

BackendStep Mc1AsciiBackend::feed(QByteArrayView bytes, qint64) {
    BackendStep step;
    m_buffer.append(bytes.toByteArray());
    const QByteArray before = m_buffer;
    while (const std::optional<QByteArray> line = takeMc1AsciiLine(m_buffer)) {
        Incoming in;
        in.message = *line;
        in.wire = before.left(before.size() - m_buffer.size());
        step.incoming << in;
    }
    return step;
}

QByteArray Mc1AsciiBackend::resetInput() {
    return std::exchange(m_buffer, {});
}

qint64 Mc1AsciiBackend::requestWireBytes(const Request& request) const {
    return request.message.size();
}

qint64 Mc1AsciiBackend::replyWireBytes(const Request& request) const {
    return request.longestReplyBytes;
}

}  // namespace cambench::comm
