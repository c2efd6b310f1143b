// SerialTransport on a real pseudo-terminal: settings, modem lines a pty
// lacks, and a port that vanishes while the link waits.
#include "pty_device.h"

#include "comm/camcon/ascii/ascii_link.h"
#include "comm/transport/serial_transport.h"

#include <QtTest>

#include <sys/stat.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

using namespace cambench;
using namespace cambench::comm;
using namespace cambench::comm::test;

class TestSerialTransport : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void openAppliesSettingsToTheLine();
    void openSucceedsThoughPtyRefusesDtrAndRts();
    void openMissingPortNamesPortAndWhatToCheck();
    void permissionDeniedSaysSoAndWhatToDo();
    void invalidSettingsAreRefused();
    void readReturnsEmptyOnQuietLine();
    void writeReachesTheDevice();
    void portDisappearingDuringWaitGivesCommunicationError();
    void callsAfterDisappearanceFailFast();
    void descriptionNamesPortAndFrame();
};

void TestSerialTransport::openAppliesSettingsToTheLine() {
    // A pty keeps the speed, the stop bits and the handshake it is given;
    // it forces 8 data bits without parity, so those cannot be checked here.
    PtyDevice device(Framing::Standard, [](const Frame&, int) { return DeviceAction{}; });
    QVERIFY(device.isValid());
    SerialTransport transport(device.slavePath(),
                              SerialSettings{19200, 8, 'N', 2, 'H', true, true});
    const Status opened = transport.open();
    QVERIFY2(opened.ok(), qPrintable(opened.error().message));

    termios tio{};
    QCOMPARE(tcgetattr(device.slaveFd(), &tio), 0);
    QCOMPARE(cfgetospeed(&tio), speed_t(B19200));
    QVERIFY(tio.c_cflag & CSTOPB);
    QVERIFY(tio.c_cflag & CRTSCTS);

    transport.close();
    SerialTransport other(device.slavePath(), SerialSettings{4800, 8, 'N', 1, 'N', true, true});
    QVERIFY(other.open().ok());
    QCOMPARE(tcgetattr(device.slaveFd(), &tio), 0);
    QCOMPARE(cfgetospeed(&tio), speed_t(B4800));
    QVERIFY(!(tio.c_cflag & CSTOPB));
    QVERIFY(!(tio.c_cflag & CRTSCTS));
}

void TestSerialTransport::openSucceedsThoughPtyRefusesDtrAndRts() {
    PtyDevice device(Framing::Standard, [](const Frame&, int) { return DeviceAction{}; });
    SerialTransport transport(device.slavePath(), SerialSettings{9600, 8, 'N', 1, 'N', true, true});
    const Status opened = transport.open();
    QVERIFY2(opened.ok(), qPrintable(opened.error().message));
    QVERIFY(transport.isOpen());
}

void TestSerialTransport::openMissingPortNamesPortAndWhatToCheck() {
    SerialTransport transport(QStringLiteral("/dev/cambench-no-such-port"), SerialSettings{});
    const Status opened = transport.open();
    QVERIFY(!opened.ok());
    QCOMPARE(opened.error().kind, ErrorKind::Communication);
    QVERIFY2(opened.error().message.contains(QLatin1String("/dev/cambench-no-such-port")),
             qPrintable(opened.error().message));
    QVERIFY2(opened.error().message.contains(QLatin1String("check")),
             qPrintable(opened.error().message));
    QVERIFY(!transport.isOpen());
}

void TestSerialTransport::permissionDeniedSaysSoAndWhatToDo() {
    // A port this user may not open: a pty with mode 000, opened by an
    // unprivileged user (root ignores file modes, so a child process drops
    // to "nobody" first when the test runs as root, as in CI).
    PtyDevice device(Framing::Standard, [](const Frame&, int) { return DeviceAction{}; });
    QVERIFY(device.isValid());
    const QByteArray path = device.slavePath().toLocal8Bit();
    QCOMPARE(::chmod(path.constData(), 0), 0);
    int pipeFds[2];
    QCOMPARE(::pipe(pipeFds), 0);
    const pid_t child = ::fork();
    QVERIFY(child >= 0);
    if (child == 0) {
        ::close(pipeFds[0]);
        if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) ::_exit(2);
        SerialTransport transport(device.slavePath(), SerialSettings{});
        const Status opened = transport.open();
        const QByteArray message = opened ? QByteArray("opened") : opened.error().message.toUtf8();
        const ssize_t written = ::write(pipeFds[1], message.constData(), size_t(message.size()));
        ::_exit(written == message.size() ? 0 : 3);
    }
    ::close(pipeFds[1]);
    QByteArray message;
    char buffer[512];
    for (ssize_t n; (n = ::read(pipeFds[0], buffer, sizeof buffer)) > 0;) message.append(buffer, n);
    ::close(pipeFds[0]);
    int status = 0;
    ::waitpid(child, &status, 0);
    QVERIFY2(WIFEXITED(status) && WEXITSTATUS(status) == 0, "the unprivileged child failed");
    const QString text = QString::fromUtf8(message);
    QVERIFY2(text.startsWith(QStringLiteral("permission denied on %1").arg(device.slavePath())),
             qPrintable(text));
    QVERIFY2(text.contains(QLatin1String("dialout")), qPrintable(text));
}

void TestSerialTransport::invalidSettingsAreRefused() {
    PtyDevice device(Framing::Standard, [](const Frame&, int) { return DeviceAction{}; });
    SerialTransport transport(device.slavePath(), SerialSettings{9600, 9, 'N', 1, 'N', true, true});
    const Status opened = transport.open();
    QVERIFY(!opened.ok());
    QCOMPARE(opened.error().kind, ErrorKind::Usage);
    QVERIFY2(opened.error().message.contains(QLatin1String("data bits")),
             qPrintable(opened.error().message));
}

void TestSerialTransport::readReturnsEmptyOnQuietLine() {
    PtyDevice device(Framing::Standard, [](const Frame&, int) { return DeviceAction{}; });
    SerialTransport transport(device.slavePath(), SerialSettings{});
    QVERIFY(transport.open().ok());
    const Result<QByteArray> bytes = transport.read(120);
    QVERIFY(bytes.ok());
    QVERIFY(bytes->isEmpty());
    QVERIFY(transport.isOpen());
}

void TestSerialTransport::writeReachesTheDevice() {
    PtyDevice device(Framing::Standard, [](const Frame&, int) { return DeviceAction{}; });
    SerialTransport transport(device.slavePath(), SerialSettings{});
    QVERIFY(transport.open().ok());
    QVERIFY(transport.write(encodeFrame(Frame{'?', "IFGWG", std::nullopt, true})).ok());
    QTRY_COMPARE(device.requestCount(), 1);
    QCOMPARE(device.requests()[0].body, QByteArray("IFGWG"));
}

void TestSerialTransport::portDisappearingDuringWaitGivesCommunicationError() {
    PtyDevice device(Framing::Standard, [](const Frame&, int) {
        return DeviceAction{{}, 0, true};
    });
    SerialTransport transport(device.slavePath(), SerialSettings{});
    QVERIFY(transport.open().ok());
    // Retries and timeout are large: only the vanished port can end this.
    AsciiLink link(transport, AsciiSettings{Framing::Standard, 0, 63, 60000, 150000, 3});
    const Result<Fields> reply = link.call('?', "UNIT");
    QVERIFY(device.hungUp());
    QVERIFY(!reply.ok());
    QCOMPARE(reply.error().kind, ErrorKind::Communication);
    QVERIFY2(reply.error().message.contains(device.slavePath()), qPrintable(reply.error().message));
    QVERIFY2(reply.error().message.contains(QLatin1String("disappeared")),
             qPrintable(reply.error().message));
    QVERIFY(!transport.isOpen());
}

void TestSerialTransport::callsAfterDisappearanceFailFast() {
    PtyDevice device(Framing::Standard, [](const Frame&, int) {
        return DeviceAction{{}, 0, true};
    });
    SerialTransport transport(device.slavePath(), SerialSettings{});
    QVERIFY(transport.open().ok());
    QVERIFY(transport.write(encodeFrame(Frame{'?', "UNIT", std::nullopt, true})).ok());
    QTRY_VERIFY(device.hungUp());
    QVERIFY(!transport.read(60000).ok());
    const Status written = transport.write("?UNIT");
    QVERIFY(!written.ok());
    QVERIFY2(written.error().message.contains(QLatin1String("disappeared")),
             qPrintable(written.error().message));
    QVERIFY(!transport.read(60000).ok());
}

void TestSerialTransport::descriptionNamesPortAndFrame() {
    SerialTransport transport(QStringLiteral("/dev/ttyUSB0"),
                              SerialSettings{38400, 8, 'E', 1, 'N', true, true});
    QCOMPARE(transport.description(), QStringLiteral("/dev/ttyUSB0 at 38400 8E1"));
}

QTEST_GUILESS_MAIN(TestSerialTransport)
#include "tst_serial_transport.moc"
