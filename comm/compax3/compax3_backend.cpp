#include "compax3_backend.h"

#include "compax3_syntax.h"

#include <QCoreApplication>

namespace cambench::comm {

QString Compax3Backend::describe() const {
    if (m_address < 0) return QCoreApplication::translate("cambench::comm", "the Compax3 (RS232)");
    return QCoreApplication::translate("cambench::comm", "the Compax3 at address %1 (RS485)")
        .arg(m_address);
}

QString Compax3Backend::checkHint() const {
    if (m_address < 0)
        return QCoreApplication::translate(
            "cambench::comm",
            "check the cable (a null-modem cable with RTS/CTS), the baud rate (115200 unless set "
            "otherwise in the C3 ServoManager) and that the drive is powered");
    return QCoreApplication::translate(
        "cambench::comm",
        "check the RS485 wiring, the baud rate and the drive's address (C3 ServoManager, "
        "\"RS485 settings\"); `c3 scan` lists the addresses that answer");
}

QByteArray Compax3Backend::requestLine(const Request& request) const {
    return compax3RequestLine(request.message, m_address);
}

qint64 Compax3Backend::requestWireBytes(const Request& request) const {
    return request.message.size() + (m_address < 0 ? 1 : 3);
}

qint64 Compax3Backend::replyWireBytes(const Request& request) const {
    return request.longestReplyBytes + 2;  // '*' and CR
}

}  // namespace cambench::comm
