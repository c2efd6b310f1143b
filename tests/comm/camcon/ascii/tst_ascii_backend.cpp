// The CamCon ASCII backend on its own: how it sorts what arrives while a
// request waits (so that a damaged reply ends the attempt at once), what it
// tells an observer, and what it lets into the traffic log.
#include "comm/camcon/ascii/ascii_backend.h"

#include <QtTest>

using namespace cambench;
using namespace cambench::comm;

namespace {

constexpr int kDevice = 5;
constexpr int kPc = 63;

Request request(const QByteArray& message) {
    Request r;
    r.message = message;
    return r;
}

QByteArray reply(const QByteArray& body, std::optional<MultiuserAddress> address = {}) {
    return encodeFrame(Frame{kReply, body, address, true});
}

// The reply header to our request: device 5 to PC 63 under `block`.
MultiuserAddress fromDevice(int block, int device = kDevice, int pc = kPc) {
    return MultiuserAddress{device, pc, block};
}

QList<Incoming::Kind> kinds(const BackendStep& step) {
    QList<Incoming::Kind> list;
    for (const Incoming& in : step.incoming) list.append(in.kind);
    return list;
}

}  // namespace

class TestAsciiBackend : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void replyIsAMessage();
    void replyWithItsLeadHitIsDamaged();
    void replyWithoutItsLineFeedIsDamaged();
    void noiseLineIsGarbage();
    void echoOfTheRequestIsNotDamage();
    void frameThatBrokeOffIsDamagedAfterTheGap();
    void multiuserLineWithOurHeaderIsDamaged();
    void multiuserFrameOfAnotherDeviceNamesItsSource();
    void frameForAnotherPcNamesNobody();
    void eepromBlocksAreMaskedInTheLog();
    void damagedReplyToASecretRequestIsMaskedWhole();
};

void TestAsciiBackend::replyIsAMessage() {
    AsciiBackend backend(Framing::Standard, 0, kPc);
    backend.beginRequest(request("?UNIT"));
    const BackendStep step = backend.feed(reply("UNIT"), 0);
    QCOMPARE(kinds(step), QList<Incoming::Kind>{Incoming::Message});
    QCOMPARE(step.incoming.first().message, QByteArray(":UNIT"));
    QCOMPARE(backend.nextTimerMs(), -1);
}

void TestAsciiBackend::replyWithItsLeadHitIsDamaged() {
    AsciiBackend backend(Framing::Standard, 0, kPc);
    backend.beginRequest(request("?NF00000"));
    QByteArray wire = reply("NF800000008000000000");
    wire[0] = 'x';
    const BackendStep step = backend.feed(wire, 0);
    QVERIFY(kinds(step).contains(Incoming::Damaged));
}

void TestAsciiBackend::replyWithoutItsLineFeedIsDamaged() {
    AsciiBackend backend(Framing::Standard, 0, kPc);
    backend.beginRequest(request("?UNIT"));
    QByteArray wire = reply("UNIT");
    wire[wire.size() - 1] = 'x';
    const BackendStep step = backend.feed(wire, 0);
    QVERIFY(kinds(step).contains(Incoming::Damaged));
}

void TestAsciiBackend::noiseLineIsGarbage() {
    AsciiBackend backend(Framing::Standard, 0, kPc);
    backend.beginRequest(request("?UNIT"));
    const BackendStep step = backend.feed(QByteArray("\x01\xff noise\r\n"), 0);
    QVERIFY(!kinds(step).isEmpty());
    QVERIFY(!kinds(step).contains(Incoming::Damaged));
    QCOMPARE(backend.nextTimerMs(), -1);
}

void TestAsciiBackend::echoOfTheRequestIsNotDamage() {
    for (const Framing framing : {Framing::Standard, Framing::Multiuser}) {
        // Device number = PC number: the echo's header looks like a reply's.
        AsciiBackend backend(framing, kPc, kPc);
        backend.beginRequest(request("?UNIT"));
        const QByteArray echo = backend.startAttempt(request("?UNIT"), 1, 0).write;
        BackendStep step = backend.feed(echo.left(4), 0);
        step.append(backend.feed(echo.mid(4), 1));
        QVERIFY(!kinds(step).contains(Incoming::Damaged));
        QCOMPARE(backend.nextTimerMs(), -1);
        const BackendStep answer = backend.feed(
            reply("UNIT",
                  framing == Framing::Multiuser ? std::optional(fromDevice(0, kPc)) : std::nullopt),
            2);
        QCOMPARE(kinds(answer), QList<Incoming::Kind>{Incoming::Message});
    }
}

void TestAsciiBackend::frameThatBrokeOffIsDamagedAfterTheGap() {
    AsciiBackend backend(Framing::Standard, 0, kPc);
    LineTiming line;
    line.baud = 38400;
    backend.setLineTiming(line);
    backend.beginRequest(request("?UNIT"));
    QByteArray wire = reply("UNIT");
    wire[wire.size() - 2] = 'x';  // the CR: the frame never ends
    QVERIFY(backend.feed(wire, 1000).incoming.isEmpty());
    QCOMPARE(backend.nextTimerMs(), 1000 + line.frameGapMs());
    QVERIFY(backend.poll(1000 + line.frameGapMs() - 1).incoming.isEmpty());
    const BackendStep step = backend.poll(1000 + line.frameGapMs());
    QCOMPARE(kinds(step), QList<Incoming::Kind>{Incoming::Damaged});
    QCOMPARE(step.incoming.first().wire, wire);  // the partial frame, for the log
    QCOMPARE(backend.nextTimerMs(), -1);
    // More bytes of the frame restart the gap.
    backend.beginRequest(request("?UNIT"));
    QVERIFY(backend.feed(wire.left(3), 2000).incoming.isEmpty());
    QVERIFY(backend.feed(wire.mid(3, 2), 2010).incoming.isEmpty());
    QCOMPARE(backend.nextTimerMs(), 2010 + line.frameGapMs());
}

void TestAsciiBackend::multiuserLineWithOurHeaderIsDamaged() {
    AsciiBackend backend(Framing::Multiuser, kDevice, kPc);
    backend.beginRequest(request("?UNIT"));  // block 0
    QByteArray ours = reply("UNIT", fromDevice(0));
    ours[3] = 'x';  // the lead
    QVERIFY(kinds(backend.feed(ours, 0)).contains(Incoming::Damaged));
    backend.beginRequest(request("?UNIT"));  // block 1
    QByteArray other = reply("UNIT", MultiuserAddress{7, 12, 9});
    other[3] = 'x';
    QVERIFY(!kinds(backend.feed(other, 0)).contains(Incoming::Damaged));
}

void TestAsciiBackend::multiuserFrameOfAnotherDeviceNamesItsSource() {
    AsciiBackend backend(Framing::Multiuser, kDevice, kPc);
    backend.beginRequest(request("?UNIT"));  // device 5, block 0
    const BackendStep step = backend.feed(reply("UNIT", fromDevice(7, 7)), 0);
    QCOMPARE(kinds(step), QList<Incoming::Kind>{Incoming::Foreign});
    QCOMPARE(step.incoming.first().source, 7);
    QCOMPARE(step.incoming.first().sequence, 7);
    const BackendStep ours = backend.feed(reply("UNIT", fromDevice(0)), 1);
    QCOMPARE(kinds(ours), QList<Incoming::Kind>{Incoming::Message});
    QCOMPARE(ours.incoming.first().source, kDevice);
}

void TestAsciiBackend::frameForAnotherPcNamesNobody() {
    AsciiBackend backend(Framing::Multiuser, kDevice, kPc);
    backend.beginRequest(request("?UNIT"));
    const BackendStep step = backend.feed(reply("UNIT", fromDevice(0, kDevice, 12)), 0);
    QCOMPARE(kinds(step), QList<Incoming::Kind>{Incoming::Foreign});
    QCOMPARE(step.incoming.first().source, -1);
}

void TestAsciiBackend::eepromBlocksAreMaskedInTheLog() {
    AsciiBackend backend(Framing::Standard, 0, kPc);
    const QByteArray data(
        "\x20"
        "4711"
        "1234\r\x1b"
        "ab",
        12);
    const QByteArray out = encodeFrame(Frame{kCommand, "EE0005" + data, std::nullopt, true});
    backend.beginRequest(request("!EE0005" + data));
    const QByteArray masked = backend.maskForLog(out, true);
    QCOMPARE(masked.size(), out.size());
    QVERIFY(masked.startsWith("!EE0005*"));
    QVERIFY(!masked.contains("4711") && !masked.contains("1234"));
    QCOMPARE(masked.right(4), out.right(4));  // checksum and CR LF stay
    QCOMPARE(backend.maskForLog(reply("EEOK"), false), reply("EEOK"));
    const QByteArray error = reply("EEERRFFFFFFD5");
    QCOMPARE(backend.maskForLog(error, false), error);

    backend.beginRequest(request("?EE0005"));
    const QByteArray in = reply("EE0005" + data);
    const QByteArray shown = backend.maskForLog(in, false);
    QVERIFY(shown.startsWith(":EE0005*"));
    QVERIFY(!shown.contains("4711") && !shown.contains("1234"));
    QCOMPARE(backend.maskForLog(encodeFrame(Frame{kQuery, "EE0005", std::nullopt, true}), true),
             encodeFrame(Frame{kQuery, "EE0005", std::nullopt, true}));
}

void TestAsciiBackend::damagedReplyToASecretRequestIsMaskedWhole() {
    AsciiBackend backend(Framing::Standard, 0, kPc);
    backend.beginRequest(request("?EE0005"));
    QByteArray in = reply("EE0005" + QByteArray("\x20"
                                                "4711"
                                                "1234"
                                                "ab",
                                                11));
    in[0] = 'x';  // no longer a frame: nobody can tell where the data is
    const QByteArray shown = backend.maskForLog(in, false);
    QVERIFY(!shown.contains("4711") && !shown.contains("1234"));
    QVERIFY(shown.endsWith("\r\n"));
    // The same bytes while a harmless request waits are shown as they are.
    backend.beginRequest(request("?UNIT"));
    QCOMPARE(backend.maskForLog(QByteArray("noise\r\n"), false), QByteArray("noise\r\n"));
}

QTEST_GUILESS_MAIN(TestAsciiBackend)
#include "tst_ascii_backend.moc"
