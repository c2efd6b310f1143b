// The real cambench-sim: started as a process, reached over its
// pseudo-terminal with QSerialPort and over TCP, stopped with SIGTERM.

#include "comm/camcon/ascii/command_codec.h"
#include "comm/camcon/ascii/stream_decoder.h"
#include "tests/e2e/child_process.h"

#include <QProcess>
#include <QSerialPort>
#include <QTcpSocket>
#include <QtTest>

using namespace cambench::comm;

namespace {

const QByteArray kEpromRequest = encodeFrame(Frame{kQuery, "EPROM", std::nullopt, true});

// Starts cambench-sim and returns the first line it prints. The simulator
// ends with this test, also when the test is killed.
QString start(QProcess& process, const QStringList& arguments) {
    cambench::e2e::endWithThisTest(process);
    process.start(QStringLiteral(CAMBENCH_SIM_EXECUTABLE), arguments);
    if (!process.waitForStarted(10000)) return {};
    while (!process.canReadLine()) {
        if (!process.waitForReadyRead(10000)) return {};
    }
    return QString::fromLocal8Bit(process.readLine()).trimmed();
}

// Reads from `device` until one reply frame is complete.
std::optional<Frame> readReply(QIODevice& device) {
    StreamDecoder decoder(Framing::Standard, ":");
    for (int i = 0; i < 100; ++i) {
        if (device.bytesAvailable() == 0 && !device.waitForReadyRead(100)) continue;
        for (const DecodeEvent& event : decoder.feed(device.readAll())) {
            if (event.kind == DecodeEvent::FrameOk) return event.frame;
        }
    }
    return std::nullopt;
}

void checkEpromReply(const std::optional<Frame>& reply) {
    QVERIFY(reply.has_value());
    const ReplyMatch match = matchReply(*findCommand(kQuery, "EPROM"), *reply);
    QCOMPARE(match.kind, ReplyMatch::Matches);
    QCOMPARE(match.fields.bytes("text"), QByteArray("11.10.1994"));
}

void stop(QProcess& process) {
    process.terminate();  // SIGTERM
    QVERIFY(process.waitForFinished(10000));
    QCOMPARE(process.exitStatus(), QProcess::NormalExit);
    QCOMPARE(process.exitCode(), 0);
}

}  // namespace

class TestSimExecutable : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void answersOverThePseudoTerminal();
    void answersOverTcp();
    void rejectsBadOptions();
};

void TestSimExecutable::answersOverThePseudoTerminal() {
    QProcess process;
    const QString path = start(process, {QStringLiteral("--no-throttle")});
    QVERIFY2(path.startsWith(QStringLiteral("/dev/")), qPrintable(path));

    QSerialPort port(path);
    QVERIFY2(port.open(QIODevice::ReadWrite), qPrintable(port.errorString()));
    // A pty has no modem lines: setting DTR/RTS fails there, and that is fine.
    port.setDataTerminalReady(true);
    port.setRequestToSend(true);
    port.clearError();
    QCOMPARE(port.write(kEpromRequest), kEpromRequest.size());
    QVERIFY(port.waitForBytesWritten(2000));
    checkEpromReply(readReply(port));
    port.close();
    stop(process);
}

void TestSimExecutable::answersOverTcp() {
    QProcess process;
    const QString address = start(process, {QStringLiteral("--tcp"), QStringLiteral("0"),
                                            QStringLiteral("--baud"), QStringLiteral("115200")});
    QVERIFY2(address.startsWith(QStringLiteral("tcp://127.0.0.1:")), qPrintable(address));
    QTcpSocket socket;
    socket.connectToHost(QStringLiteral("127.0.0.1"),
                         quint16(address.section(QLatin1Char(':'), -1).toUInt()));
    QVERIFY(socket.waitForConnected(5000));
    socket.write(kEpromRequest);
    checkEpromReply(readReply(socket));
    stop(process);
}

void TestSimExecutable::rejectsBadOptions() {
    QProcess process;
    cambench::e2e::endWithThisTest(process);
    process.start(QStringLiteral(CAMBENCH_SIM_EXECUTABLE),
                  {QStringLiteral("--devices"), QStringLiteral("0,99")});
    QVERIFY(process.waitForFinished(10000));
    QCOMPARE(process.exitCode(), 2);
    QVERIFY(process.readAllStandardError().contains("0..63"));
    // A Compax3 address without RS485 says what is missing.
    process.start(QStringLiteral(CAMBENCH_SIM_EXECUTABLE),
                  {QStringLiteral("--family"), QStringLiteral("compax3"),
                   QStringLiteral("--address"), QStringLiteral("5")});
    QVERIFY(process.waitForFinished(10000));
    QCOMPARE(process.exitCode(), 2);
    QVERIFY(process.readAllStandardError().contains("--address is for RS485: add --rs485"));
    // A variant the MC-1 simulator does not know is named with those it does.
    process.start(QStringLiteral(CAMBENCH_SIM_EXECUTABLE),
                  {QStringLiteral("--family"), QStringLiteral("mc1"), QStringLiteral("--variant"),
                   QStringLiteral("mc300")});
    QVERIFY(process.waitForFinished(10000));
    QCOMPARE(process.exitCode(), 2);
    QVERIFY(process.readAllStandardError().contains("mc100v1, mc100v2, mc200v1, mc200v2"));
}

QTEST_GUILESS_MAIN(TestSimExecutable)
#include "tst_sim_executable.moc"
