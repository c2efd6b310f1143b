// The simulated bus: Multiuser addressing, repeated blocks, checksums,
// fault injection, pacing, port strings and the in-process transport.

#include "sim_test_client.h"

#include "comm/sim/camcon/camcon_simulator.h"
#include "comm/sim/camcon/sim_demo.h"
#include "comm/sim/camcon/sim_port_config.h"
#include "comm/sim/sim_pacer.h"
#include "comm/sim/sim_transport.h"

#include <QtTest>

using namespace cambench;
using namespace cambench::comm;
using cambench::comm::test::SimTestClient;

namespace {

std::unique_ptr<SimLine> multiuserLine(const QList<int>& devices) {
    SimPortConfig config;
    config.devices = devices;
    return makeSimLine(config);
}

Fields cam(qint64 on, qint64 off) {
    return Fields().set("program", 7).set("output", 1).set("on", on).set("off", off);
}

}  // namespace

class TestSimLine : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void onlyTheAddressedDeviceAnswers();
    void repeatedBlockRepeatsWithoutExecuting();
    void otherPcNumberIsIgnoredWhenSet();
    void badChecksumGetsNoAnswer();
    void faultRatesFollowTheSeed();
    void deadDeviceNeverAnswers();
    void fixedDelayIsAdded();
    void pacerTiming();
    void pacedQueueHandsOutBytesInOrder();
    void portStringKeys();
    void portStringErrors_data();
    void portStringErrors();
    void transportDeliversReplies();
};

void TestSimLine::onlyTheAddressedDeviceAnswers() {
    auto line = multiuserLine({0, 5});
    QCOMPARE(line->framing(), Framing::Multiuser);
    SimTestClient pc(*line, 62);
    pc.setDevice(5);
    const QList<SimOutput> out = line->feed(pc.requestBytes(kQuery, "EPROM", {}, 9));
    QCOMPARE(out.size(), 1);
    QCOMPARE(quint8(out.first().bytes.at(0)), 0x40 + 5);
    QCOMPARE(quint8(out.first().bytes.at(1)), 0x80 + 62);
    QCOMPARE(quint8(out.first().bytes.at(2)), 0xC0 + 9);
    QCOMPARE(line->device(5)->executions(), 1);
    QCOMPARE(line->device(0)->executions(), 0);

    pc.setDevice(17);  // nobody there
    QVERIFY(line->feed(pc.requestBytes(kQuery, "UNIT", {}, 10)).isEmpty());
    QCOMPARE(line->counters().unaddressed, 1);
    pc.setDevice(0);
    QCOMPARE(pc.call(kQuery, "UNIT").kind, ReplyMatch::Matches);
    QCOMPARE(line->device(0)->executions(), 1);
    QCOMPARE(pc.call(kQuery, "GSIO").fields.num("value"),
             2);  // the device says it speaks Multiuser
    QCOMPARE(pc.call(kQuery, "GNR").fields.num("value"), 0);
}

void TestSimLine::repeatedBlockRepeatsWithoutExecuting() {
    auto line = multiuserLine({0, 5});
    SimTestClient pc(*line);
    pc.setDevice(5);
    const QByteArray request = pc.requestBytes(kCommand, "NINS", cam(10, 20), 33);
    const QList<SimOutput> first = line->feed(request);
    const QList<SimOutput> again = line->feed(request);
    QCOMPARE(first.size(), 1);
    QCOMPARE(again.size(), 1);
    QCOMPARE(again.first().bytes, first.first().bytes);  // OK twice, not OK then overlap error
    QCOMPARE(line->device(5)->executions(), 1);
    QCOMPARE(line->counters().repeats, 1);
    QCOMPARE(line->device(5)->state().cams.track(7, 1).size(), 1);

    // A new block number executes again: now the cam overlaps.
    const QList<Frame> frames =
        pc.replies(line->feed(pc.requestBytes(kCommand, "NINS", cam(10, 20), 34)));
    QCOMPARE(frames.size(), 1);
    QCOMPARE(matchReply(*findCommand(kCommand, "NINS"), frames.first()).errorCode, -1);
    QCOMPARE(line->device(5)->executions(), 2);
}

void TestSimLine::otherPcNumberIsIgnoredWhenSet() {
    auto line = multiuserLine({0, 5});
    line->setPcNumber(63);
    SimTestClient stranger(*line, 40);
    QVERIFY(line->feed(stranger.requestBytes(kQuery, "UNIT", {}, 1)).isEmpty());
    SimTestClient pc(*line, 63);
    QCOMPARE(pc.call(kQuery, "UNIT").kind, ReplyMatch::Matches);
}

void TestSimLine::badChecksumGetsNoAnswer() {
    auto line = makeSimLine({});
    QByteArray request = SimTestClient(*line).requestBytes(kQuery, "EPROM", {}, 0);
    request[request.size() - 3] = request.at(request.size() - 3) == '0' ? '1' : '0';
    QVERIFY(line->feed(request).isEmpty());
    QCOMPARE(line->counters().badChecksums, 1);
    QCOMPARE(line->device(0)->executions(), 0);
}

void TestSimLine::faultRatesFollowTheSeed() {
    SimPortConfig config;
    config.faults.corruptProbability = 0.25;
    config.faults.dropProbability = 0.1;
    config.faults.seed = 4711;
    const auto run = [&config] {
        auto line = makeSimLine(config);
        SimTestClient pc(*line);
        QList<QByteArray> wire;
        for (int i = 0; i < 1000; ++i) {
            const QList<SimOutput> out = line->feed(pc.requestBytes(kQuery, "EPROM", {}, 0));
            wire.append(out.isEmpty() ? QByteArray() : out.first().bytes);
        }
        return std::make_pair(line->faults().counters(), wire);
    };
    const auto [counters, wire] = run();
    QCOMPARE(counters.replies, 1000);
    QVERIFY2(counters.dropped > 60 && counters.dropped < 140,
             qPrintable(QString::number(counters.dropped)));
    QVERIFY2(counters.corrupted > 180 && counters.corrupted < 270,
             qPrintable(QString::number(counters.corrupted)));
    QCOMPARE(wire.count(QByteArray()), counters.dropped);
    auto clean = makeSimLine({});
    const QByteArray good =
        clean->feed(SimTestClient(*clean).requestBytes(kQuery, "EPROM", {}, 0)).first().bytes;
    const auto changed = std::count_if(wire.begin(), wire.end(), [&good](const QByteArray& w) {
        return !w.isEmpty() && w != good;
    });
    QCOMPARE(int(changed), counters.corrupted);

    const auto [again, wireAgain] = run();
    QCOMPARE(again.dropped, counters.dropped);
    QCOMPARE(again.corrupted, counters.corrupted);
    QCOMPARE(wireAgain, wire);
}

void TestSimLine::deadDeviceNeverAnswers() {
    SimPortConfig config;
    config.faults.dead = true;
    auto line = makeSimLine(config);
    SimTestClient pc(*line);
    QCOMPARE(pc.call(kQuery, "EPROM").kind, ReplyMatch::Unrelated);
    QCOMPARE(line->faults().counters().dropped, 1);
}

void TestSimLine::fixedDelayIsAdded() {
    SimPortConfig config;
    config.faults.extraDelayMs = 250;
    auto line = makeSimLine(config);
    const QList<SimOutput> out =
        line->feed(SimTestClient(*line).requestBytes(kQuery, "EPROM", {}, 0));
    QCOMPARE(out.size(), 1);
    QCOMPARE(out.first().delayMs, SimProfile().processingDelayMs + 250);
}

void TestSimLine::pacerTiming() {
    SimPacer pacer(9600);
    QCOMPARE(pacer.transferUs(96), 100000);  // 96 bytes * 10 bits / 9600 baud = 0.1 s
    const QList<PacedReply> replies =
        pacer.schedule(1000, 96, {{QByteArray(48, 'a'), 5}, {QByteArray(96, 'b'), 0}});
    QCOMPARE(replies.size(), 2);
    // Arrives at 1 ms + 100 ms, the device works 5 ms, 48 bytes take 50 ms.
    QCOMPARE(replies.at(0).startUs, 106000);
    QCOMPARE(replies.at(0).endUs(), 156000);
    QCOMPARE(replies.at(0).bytesDueAt(105999), 0);
    QCOMPARE(replies.at(0).bytesDueAt(106000 + 10417), 10);
    QCOMPARE(replies.at(0).bytesDueAt(999999), 48);
    QCOMPARE(replies.at(1).startUs, 156000);  // waits for the line
    QCOMPARE(replies.at(1).endUs(), 256000);
    // A second request queues behind the first on the way to the device.
    QCOMPARE(pacer.schedule(0, 96, {{QByteArray(1, 'c'), 0}}).first().startUs, 256000);

    SimPacer fast(9600, false);
    const QList<PacedReply> instant = fast.schedule(1000, 96, {{QByteArray(48, 'a'), 5}});
    QCOMPARE(instant.first().startUs, 6000);
    QCOMPARE(instant.first().bytesDueAt(6000), 48);
}

void TestSimLine::pacedQueueHandsOutBytesInOrder() {
    SimPacer pacer(10000);  // 1 ms per byte
    PacedQueue queue;
    queue.append(pacer.schedule(0, 0, {{"abc", 0}, {"de", 0}}));
    QCOMPARE(queue.nextDueUs(), std::optional<qint64>(1000));
    QCOMPARE(queue.takeDue(2000), QByteArray("ab"));
    QCOMPARE(queue.takeDue(2500), QByteArray());
    QCOMPARE(queue.takeDue(4000), QByteArray("cd"));
    QCOMPARE(queue.takeDue(99999), QByteArray("e"));
    QVERIFY(!queue.nextDueUs());
}

void TestSimLine::portStringKeys() {
    SerialSettings serial;
    serial.baud = 19200;
    Result<SimPortConfig> plain = parseSimPort(QStringLiteral("sim"), serial);
    QVERIFY(plain.ok());
    QCOMPARE(plain->devices, QList<int>{0});
    QCOMPARE(plain->baud, 19200);
    QCOMPARE(plain->effectiveFraming(), Framing::Standard);

    Result<SimPortConfig> full =
        parseSimPort(QStringLiteral("sim:devices=0,5;baud=38400;corrupt=0.01;drop=0.2;delay=5;seed="
                                    "7;throttle=0;fill=3;dead=1"),
                     serial);
    QVERIFY2(full.ok(), qPrintable(full.error().message));
    QCOMPARE(full->devices, (QList<int>{0, 5}));
    QCOMPARE(full->effectiveFraming(), Framing::Multiuser);
    QCOMPARE(full->baud, 38400);
    QCOMPARE(full->faults.corruptProbability, 0.01);
    QCOMPARE(full->faults.dropProbability, 0.2);
    QCOMPARE(full->faults.extraDelayMs, 5);
    QCOMPARE(full->faults.seed, 7u);
    QCOMPARE(full->throttle, false);
    QCOMPARE(full->fill, 3);
    QCOMPARE(full->faults.dead, true);

    Result<SimPortConfig> single =
        parseSimPort(QStringLiteral("sim:framing=multiuser;devices=9"), serial);
    QVERIFY(single.ok());
    QCOMPARE(single->effectiveFraming(), Framing::Multiuser);

    // Another identity: the device on the line says it (?EPROM, ?AMAX).
    Result<SimPortConfig> other =
        parseSimPort(QStringLiteral("sim:eprom=03.05.2001;outputs=16;throttle=0"), serial);
    QVERIFY2(other.ok(), qPrintable(other.error().message));
    const std::unique_ptr<SimLine> line = makeSimLine(*other);
    QCOMPARE(line->device(0)->profile().epromDate, QByteArray("03.05.2001"));
    QCOMPARE(line->device(0)->profile().outputs, 16);
}

void TestSimLine::portStringErrors_data() {
    QTest::addColumn<QString>("port");
    QTest::addColumn<QString>("mentions");
    QTest::newRow("unknown key") << "sim:speed=3"
                                 << "unknown key \"speed\"";
    QTest::newRow("no value") << "sim:devices"
                              << "not key=value";
    QTest::newRow("device out of range") << "sim:devices=64"
                                         << "0..63";
    QTest::newRow("bad probability") << "sim:corrupt=1.5"
                                     << "probability";
    QTest::newRow("bad framing") << "sim:framing=cambus"
                                 << "standard or multiuser";
    QTest::newRow("two devices standard") << "sim:framing=standard;devices=1,2"
                                          << "one device";
    QTest::newRow("bad firmware date") << "sim:eprom=2001-05-03"
                                       << "dd.mm.yyyy";
    QTest::newRow("too many outputs") << "sim:outputs=65"
                                      << "outputs 1..64";
    QTest::newRow("not sim") << "simulator"
                             << "not a simulator port";
}

void TestSimLine::portStringErrors() {
    QFETCH(QString, port);
    QFETCH(QString, mentions);
    const Result<SimPortConfig> config = parseSimPort(port, {});
    QVERIFY(!config.ok());
    QCOMPARE(config.error().kind, ErrorKind::Usage);
    QVERIFY2(config.error().message.contains(mentions), qPrintable(config.error().message));
    QVERIFY(!makeCamConSimTransport(port, {}).ok());
}

void TestSimLine::transportDeliversReplies() {
    Result<std::unique_ptr<Transport>> made =
        makeCamConSimTransport(QStringLiteral("sim:baud=115200"), {});
    QVERIFY(made.ok());
    Transport& transport = *made.value();
    QVERIFY(!transport.write("?EPROM4F\r\n").ok());  // not open yet
    QVERIFY(transport.open().ok());
    QVERIFY(transport.description().contains(QStringLiteral("115200")));
    Frame request;
    request.body = "EPROM";
    QVERIFY(transport.write(encodeFrame(request)).ok());
    QByteArray received;
    for (int i = 0; i < 100 && !received.endsWith("\r\n"); ++i) {
        const Result<QByteArray> chunk = transport.read(50);
        QVERIFY(chunk.ok());
        received += *chunk;
    }
    QVERIFY2(received.startsWith(QByteArray(":EPROM11.10.1994", 16)), received.toHex().constData());
    // A quiet line reads empty after the timeout.
    const Result<QByteArray> quiet = transport.read(20);
    QVERIFY(quiet.ok());
    QVERIFY(quiet->isEmpty());
    transport.close();
    QVERIFY(!transport.read(1).ok());
}

QTEST_GUILESS_MAIN(TestSimLine)
#include "tst_sim_line.moc"
