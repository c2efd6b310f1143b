#pragma once

#include "sim_endpoint.h"
#include "sim_pacer.h"
#include "sim_reply_scheduler.h"

#include "model/result.h"

#include <QObject>
#include <QPointer>
#include <QTcpServer>
#include <QTcpSocket>

namespace cambench::comm {

// Serves a SimEndpoint on a TCP port, like a serial device server. One client
// at a time; a second one is turned away until the first disconnects.
class SimTcpServer : public QObject {
    Q_OBJECT

public:
    SimTcpServer(SimEndpoint& line, const SimPacer& pacer, QObject* parent = nullptr);
    ~SimTcpServer() override;

    // Port 0 picks a free port; port() tells which.
    Status listen(quint16 port);
    quint16 port() const { return m_server.serverPort(); }

private:
    void onNewConnection();

    QTcpServer m_server;
    QPointer<QTcpSocket> m_client;
    SimReplyScheduler m_scheduler;
};

}  // namespace cambench::comm
