#include "guarded_transport.h"

#include <QCoreApplication>

namespace cambench::comm {

GuardedTransport::GuardedTransport()
    : m_reason(QCoreApplication::translate("cambench::comm",
                                           "not connected to a device; connect first")) {}

GuardedTransport::~GuardedTransport() {
    close();
}

void GuardedTransport::attach(std::unique_ptr<Transport> transport) {
    close();
    m_inner = std::move(transport);
    m_lossMessage.clear();
}

void GuardedTransport::detach(const QString& reason) {
    close();
    m_inner.reset();
    m_reason = reason;
}

QString GuardedTransport::lossMessage() const {
    if (!m_lossMessage.isEmpty()) return m_lossMessage;
    return QCoreApplication::translate("cambench::comm",
                                       "the connection %1 closed; reconnect and retry")
        .arg(m_inner ? m_inner->description() : QString());
}

void GuardedTransport::noteFailure(const Error& error) {
    if (m_inner && !m_inner->isOpen() && m_lossMessage.isEmpty()) m_lossMessage = error.message;
}

Status GuardedTransport::open() {
    if (!m_inner) return notConnected();
    return m_inner->open();
}

void GuardedTransport::close() {
    if (m_inner) m_inner->close();
}

bool GuardedTransport::isOpen() const {
    return m_inner && m_inner->isOpen();
}

Status GuardedTransport::write(const QByteArray& bytes) {
    if (!m_inner) return notConnected();
    Status status = m_inner->write(bytes);
    if (!status) noteFailure(status.error());
    return status;
}

Result<QByteArray> GuardedTransport::read(int timeoutMs) {
    if (!m_inner) return notConnected();
    Result<QByteArray> bytes = m_inner->read(timeoutMs);
    if (!bytes) noteFailure(bytes.error());
    return bytes;
}

void GuardedTransport::discardInput() {
    if (m_inner) m_inner->discardInput();
}

QString GuardedTransport::description() const {
    return m_inner ? m_inner->description()
                   : QCoreApplication::translate("cambench::comm", "no connection");
}

}  // namespace cambench::comm
