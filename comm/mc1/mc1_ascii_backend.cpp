#include "mc1_ascii_backend.h"

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

qint64 Mc1AsciiBackend::requestWireBytes(const Request& request) const {
    return request.message.size();
}

qint64 Mc1AsciiBackend::replyWireBytes(const Request& request) const {
    return request.longestReplyBytes;
}

}  // namespace cambench::comm
