// TcpTransport against a QTcpServer playing a serial device server. The
// link runs on its own thread (as in the worker), the server on the test's
// event loop.
#include "pty_device.h"

#include "comm/camcon/ascii/ascii_link.h"
#include "comm/camcon/ascii/stream_decoder.h"
#include "comm/transport/tcp_transport.h"

#include <QTcpServer>
#include <QTcpSocket>
#include <QThread>
#include <QtTest>

#include <memory>
#include <optional>

using namespace cambench;
using namespace cambench::comm;
using namespace cambench::comm::test;

namespace {

// Answers every request on every connection as the script says; hangUp
// closes the connection.
class ScriptedServer {
public:
    explicit ScriptedServer(PtyDevice::Script script) : m_script(std::move(script)) {
        QObject::connect(&m_server, &QTcpServer::newConnection, [this] { accept(); });
        m_server.listen(QHostAddress::LocalHost);
    }
    quint16 port() const { return m_server.serverPort(); }
    int requestCount() const { return m_requests; }

private:
    void accept() {
        QTcpSocket* socket = m_server.nextPendingConnection();
        auto decoder = std::make_shared<StreamDecoder>(Framing::Standard, QByteArray("?!"));
        QObject::connect(socket, &QTcpSocket::readyRead, socket, [this, socket, decoder] {
            for (const DecodeEvent& event : decoder->feed(socket->readAll())) {
                if (event.kind != DecodeEvent::FrameOk) continue;
                const DeviceAction action = m_script(event.frame, m_requests++);
                for (const QByteArray& chunk : action.chunks) socket->write(chunk);
                socket->flush();
                if (action.hangUp) {
                    socket->disconnectFromHost();
                    return;
                }
            }
        });
    }

    PtyDevice::Script m_script;
    QTcpServer m_server;
    int m_requests = 0;
};

// Opens a TcpTransport to `port` on a thread of its own and makes one call.
Result<Fields> callOnThread(quint16 port, const char* name, int timeoutMs) {
    std::optional<Result<Fields>> result;
    std::unique_ptr<QThread> thread(QThread::create([&] {
        TcpTransport transport(QStringLiteral("127.0.0.1"), port, 2000);
        const Status opened = transport.open();
        if (!opened) {
            result = opened.error();
            return;
        }
        AsciiLink link(transport, AsciiSettings{Framing::Standard, 0, 63, timeoutMs, 150000, 2});
        result = link.call('?', name);
    }));
    thread->start();
    // Bounds a hang only; the server needs this loop to answer.
    if (!QTest::qWaitFor([&] { return thread->isFinished(); }, 60000)) {
        thread->wait();
        return Error::communication(QStringLiteral("test: the call did not return"));
    }
    return *result;
}

}  // namespace

class TestTcpTransport : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void callOverTcpDecodesReply();
    void peerClosingMidTransferGivesCommunicationError();
    void connectionRefusedNamesAddress();
    void descriptionIsTheUrl();
};

void TestTcpTransport::callOverTcpDecodesReply() {
    ScriptedServer server(
        [](const Frame& request, int) { return DeviceAction{{replyTo(request, "UNIT")}}; });
    QVERIFY(server.port() != 0);
    const Result<Fields> reply = callOnThread(server.port(), "UNIT", 5000);
    QVERIFY2(reply.ok(), qPrintable(reply.error().message));
    QCOMPARE(server.requestCount(), 1);
}

void TestTcpTransport::peerClosingMidTransferGivesCommunicationError() {
    // Half a reply, then the device server drops the connection; the long
    // timeout means only the close can end the call.
    ScriptedServer server([](const Frame& request, int) {
        return DeviceAction{{replyTo(request, "UNIT").left(3)}, 0, true};
    });
    const Result<Fields> reply = callOnThread(server.port(), "UNIT", 60000);
    QVERIFY(!reply.ok());
    QCOMPARE(reply.error().kind, ErrorKind::Communication);
    QVERIFY2(reply.error().message.contains(QLatin1String("closed the connection")),
             qPrintable(reply.error().message));
    QVERIFY2(
        reply.error().message.contains(QStringLiteral("tcp://127.0.0.1:%1").arg(server.port())),
        qPrintable(reply.error().message));
    QCOMPARE(server.requestCount(), 1);
}

void TestTcpTransport::connectionRefusedNamesAddress() {
    quint16 unusedPort = 0;
    {
        QTcpServer probe;
        QVERIFY(probe.listen(QHostAddress::LocalHost));
        unusedPort = probe.serverPort();
    }
    const Result<Fields> reply = callOnThread(unusedPort, "UNIT", 1000);
    QVERIFY(!reply.ok());
    QCOMPARE(reply.error().kind, ErrorKind::Communication);
    QVERIFY2(reply.error().message.contains(QStringLiteral("tcp://127.0.0.1:%1").arg(unusedPort)),
             qPrintable(reply.error().message));
}

void TestTcpTransport::descriptionIsTheUrl() {
    TcpTransport transport(QStringLiteral("10.0.0.5"), 4001);
    QCOMPARE(transport.description(), QStringLiteral("tcp://10.0.0.5:4001"));
    QVERIFY(!transport.isOpen());
    QVERIFY(!transport.read(0).ok());
}

QTEST_GUILESS_MAIN(TestTcpTransport)
#include "tst_tcp_transport.moc"
