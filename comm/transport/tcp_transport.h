#pragma once

#include "transport.h"

#include <memory>

class QTcpSocket;

namespace cambench::comm {

// A serial device server reached as "tcp://host:port". Like SerialTransport,
// the socket is created by open() on the worker thread and every wait is cut
// into slices of at most kSliceMs.
class TcpTransport : public Transport {
public:
    static constexpr int kSliceMs = 50;
    static constexpr int kConnectTimeoutMs = 5000;

    TcpTransport(QString host, quint16 port, int connectTimeoutMs = kConnectTimeoutMs);
    ~TcpTransport() override;

    Status open() override;
    void close() override;
    bool isOpen() const override;
    Status write(const QByteArray& bytes) override;
    Result<QByteArray> read(int timeoutMs) override;
    void discardInput() override;
    QString description() const override;

private:
    Error lose();
    Error notOpenError() const;

    QString m_host;
    quint16 m_port;
    int m_connectTimeoutMs;
    std::unique_ptr<QTcpSocket> m_socket;
    QString m_lostMessage;
};

}  // namespace cambench::comm
