#include "tcp_transport.h"

#include "transport_logging.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QTcpSocket>

#include <algorithm>

namespace cambench::comm {

namespace {

constexpr int kWriteTimeoutMs = 5000;

int sliceOf(const QDeadlineTimer& deadline, int sliceMs) {
    return int(std::min<qint64>(sliceMs, deadline.remainingTime()));
}

}  // namespace

TcpTransport::TcpTransport(QString host, quint16 port, int connectTimeoutMs)
    : m_host(std::move(host)), m_port(port), m_connectTimeoutMs(connectTimeoutMs) {}

TcpTransport::~TcpTransport() = default;

Status TcpTransport::open() {
    close();
    m_lostMessage.clear();
    m_socket = std::make_unique<QTcpSocket>();
    m_socket->connectToHost(m_host, m_port);
    QDeadlineTimer deadline(m_connectTimeoutMs);
    while (m_socket->state() != QAbstractSocket::ConnectedState) {
        if (m_socket->waitForConnected(sliceOf(deadline, kSliceMs))) break;
        const bool failed = m_socket->error() != QAbstractSocket::SocketTimeoutError &&
                            m_socket->error() != QAbstractSocket::UnknownSocketError;
        if (failed || deadline.hasExpired()) {
            const QString reason =
                failed ? m_socket->errorString()
                       : QCoreApplication::translate("cambench::comm", "no answer within %1 ms")
                             .arg(m_connectTimeoutMs);
            m_socket.reset();
            return Error::communication(
                QCoreApplication::translate(
                    "cambench::comm",
                    "cannot connect to %1: %2; check the address, the port and "
                    "that the device server is switched on")
                    .arg(description(), reason));
        }
    }
    // Small request frames must not wait for Nagle's algorithm.
    m_socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
    qCInfo(commSerialLog) << "connected to" << description();
    return success();
}

void TcpTransport::close() {
    if (!m_socket) return;
    m_socket->abort();
    m_socket.reset();
    qCInfo(commSerialLog) << "closed" << description();
}

bool TcpTransport::isOpen() const {
    return m_socket && m_socket->state() == QAbstractSocket::ConnectedState;
}

Error TcpTransport::lose() {
    if (m_socket->error() == QAbstractSocket::RemoteHostClosedError ||
        m_socket->state() != QAbstractSocket::ConnectedState)
        m_lostMessage = QCoreApplication::translate("cambench::comm",
                                                    "the device server %1 closed the connection; "
                                                    "reconnect and retry")
                            .arg(description());
    else
        m_lostMessage =
            QCoreApplication::translate("cambench::comm",
                                        "the connection to %1 failed: %2; reconnect and retry")
                .arg(description(), m_socket->errorString());
    qCWarning(commSerialLog) << m_lostMessage;
    close();
    return Error::communication(m_lostMessage);
}

Error TcpTransport::notOpenError() const {
    if (!m_lostMessage.isEmpty()) return Error::communication(m_lostMessage);
    return Error::communication(
        QCoreApplication::translate("cambench::comm", "not connected to %1; connect first")
            .arg(description()));
}

Status TcpTransport::write(const QByteArray& bytes) {
    if (!m_socket) return notOpenError();
    if (!isOpen() || m_socket->write(bytes) != bytes.size()) return lose();
    QDeadlineTimer deadline(kWriteTimeoutMs);
    while (m_socket->bytesToWrite() > 0) {
        if (!m_socket->waitForBytesWritten(sliceOf(deadline, kSliceMs)) && !isOpen()) return lose();
        if (deadline.hasExpired() && m_socket->bytesToWrite() > 0)
            return Error::communication(
                QCoreApplication::translate(
                    "cambench::comm",
                    "could not send %1 bytes to %2 within %3 ms; check the network")
                    .arg(bytes.size())
                    .arg(description())
                    .arg(kWriteTimeoutMs));
    }
    return success();
}

Result<QByteArray> TcpTransport::read(int timeoutMs) {
    if (!m_socket) return notOpenError();
    QDeadlineTimer deadline(std::max(0, timeoutMs));
    while (m_socket->bytesAvailable() == 0) {
        if (!isOpen()) return lose();
        m_socket->waitForReadyRead(sliceOf(deadline, kSliceMs));
        if (deadline.hasExpired()) break;
    }
    // Bytes that arrived together with the peer's close are still delivered;
    // the loss shows on the next read.
    if (m_socket->bytesAvailable() == 0 && !isOpen()) return lose();
    return m_socket->readAll();
}

void TcpTransport::discardInput() {
    if (m_socket) m_socket->readAll();
}

QString TcpTransport::description() const {
    return QStringLiteral("tcp://%1:%2").arg(m_host).arg(m_port);
}

}  // namespace cambench::comm
