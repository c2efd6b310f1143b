#include "comm/transport/transport_registry.h"

#include <QtTest>

using namespace cambench;
using namespace cambench::comm;

namespace {

Result<std::unique_ptr<Transport>> make(const QString& port, SerialSettings serial = {}) {
    return makeTransport(ConnectionSettings{port, serial, {}});
}

}  // namespace

class TestTransportFactory : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void serialPathMakesSerialTransport();
    void tcpUrlMakesTcpTransport();
    void simMakesSimulator();
    void invalidNamesAreUsageErrors_data();
    void invalidNamesAreUsageErrors();
};

void TestTransportFactory::serialPathMakesSerialTransport() {
    const auto transport =
        make(QStringLiteral("/dev/ttyUSB0"), SerialSettings{38400, 8, 'N', 1, 'N', true, true});
    QVERIFY2(transport.ok(), qPrintable(transport.error().message));
    QCOMPARE((*transport)->description(), QStringLiteral("/dev/ttyUSB0 at 38400 8N1"));
    QVERIFY(!(*transport)->isOpen());
}

void TestTransportFactory::tcpUrlMakesTcpTransport() {
    const auto transport = make(QStringLiteral("tcp://10.0.0.5:4001"));
    QVERIFY2(transport.ok(), qPrintable(transport.error().message));
    QCOMPARE((*transport)->description(), QStringLiteral("tcp://10.0.0.5:4001"));
}

void TestTransportFactory::simMakesSimulator() {
    auto transport = make(QStringLiteral("sim"));
    QVERIFY2(transport.ok(), qPrintable(transport.error().message));
    QVERIFY((*transport)->open().ok());
    QVERIFY((*transport)->isOpen());
}

void TestTransportFactory::invalidNamesAreUsageErrors_data() {
    QTest::addColumn<QString>("port");
    QTest::addColumn<QString>("mentions");
    QTest::newRow("empty") << QString() << QStringLiteral("no port");
    QTest::newRow("tcp without port")
        << QStringLiteral("tcp://10.0.0.5") << QStringLiteral("tcp://host:port");
    QTest::newRow("tcp without host")
        << QStringLiteral("tcp://:4001") << QStringLiteral("tcp://host:port");
    QTest::newRow("tcp with path")
        << QStringLiteral("tcp://10.0.0.5:4001/x") << QStringLiteral("tcp://host:port");
    QTest::newRow("unknown scheme")
        << QStringLiteral("udp://10.0.0.5:4001") << QStringLiteral("unknown scheme");
    QTest::newRow("bad sim option")
        << QStringLiteral("sim:nonsense=1") << QStringLiteral("nonsense");
}

void TestTransportFactory::invalidNamesAreUsageErrors() {
    QFETCH(QString, port);
    QFETCH(QString, mentions);
    const auto transport = make(port);
    QVERIFY(!transport.ok());
    QCOMPARE(transport.error().kind, ErrorKind::Usage);
    QVERIFY2(transport.error().message.contains(mentions), qPrintable(transport.error().message));
}

QTEST_GUILESS_MAIN(TestTransportFactory)
#include "tst_transport_factory.moc"
