#include "sim_tcp_server.h"

#include "sim_log.h"

#include <QHostAddress>

namespace cambench::comm {

SimTcpServer::SimTcpServer(SimEndpoint& line, const SimPacer& pacer, QObject* parent)
    : QObject(parent), m_scheduler(line, pacer, [this](const QByteArray& bytes) {
          if (m_client) m_client->write(bytes);
      }) {
    connect(&m_server, &QTcpServer::newConnection, this, &SimTcpServer::onNewConnection);
}

// The client socket is a child of m_server, which outlives m_scheduler:
// without this its "disconnected" signal would reach the destroyed
// scheduler while m_server tears the socket down.
SimTcpServer::~SimTcpServer() {
    if (m_client) QObject::disconnect(m_client, nullptr, this, nullptr);
}

Status SimTcpServer::listen(quint16 port) {
    if (!m_server.listen(QHostAddress::Any, port)) {
        return Error::communication(QStringLiteral("Cannot listen on TCP port %1: %2.")
                                        .arg(port)
                                        .arg(m_server.errorString()));
    }
    return success();
}

void SimTcpServer::onNewConnection() {
    while (QTcpSocket* socket = m_server.nextPendingConnection()) {
        if (m_client) {
            qCInfo(commSimLog) << "turned away a second client from"
                               << socket->peerAddress().toString();
            socket->disconnectFromHost();
            socket->deleteLater();
            continue;
        }
        m_client = socket;
        // A serial device server sends what the line delivers at once;
        // Nagle's algorithm would hold the rest of a reply back until the
        // PC acknowledges its start (a delayed ACK: 40 ms and more).
        socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        m_scheduler.reset();
        qCInfo(commSimLog) << "client connected from" << socket->peerAddress().toString();
        connect(socket, &QTcpSocket::readyRead, this,
                [this, socket] { m_scheduler.received(socket->readAll()); });
        connect(socket, &QTcpSocket::disconnected, this, [this, socket] {
            qCInfo(commSimLog) << "client disconnected";
            m_scheduler.reset();
            socket->deleteLater();
        });
    }
}

}  // namespace cambench::comm
