// The simulated CamCon driven through its line with catalogue-encoded
// requests: cam search cursor, editing, settings, users, EEPROM transfer.

#include "sim_test_client.h"

#include "comm/sim/camcon/sim_demo.h"
#include "comm/sim/camcon/sim_device.h"
#include "comm/sim/camcon/sim_eeprom_format.h"
#include "comm/sim/camcon/sim_handlers.h"

#include <QtTest>

using namespace cambench::comm;
using cambench::comm::test::SimTestClient;

namespace {

constexpr qint64 kNoCam = -qint64(0x80000000LL);

Fields track(int program, int output) {
    return Fields().set("program", program).set("output", output);
}
Fields cam(int program, int output, qint64 on, qint64 off) {
    return track(program, output).set("on", on).set("off", off);
}

std::unique_ptr<SimLine> demoLine(const SimProfile& profile = {}) {
    SimPortConfig config;
    return makeSimLine(config, profile);
}

}  // namespace

class TestSimDevice : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void searchWalksTheTrackWithFlags();
    void emptyTrackAnswersNoCam();
    void searchWithoutSelectedTrackIsAnError();
    void insertRejectsOverlapAndRange();
    void deleteAndChangeNeedAnExistingCam();
    void programAndTrackCopies();
    void deadTimeAboveMaximumIsRejected();
    void unknownCommandGetsNotUnderstood();
    void settingsKeepValuesAndCheckRanges();
    void specialEncoderPageSetsTextsAndType();
    void usersWalkCreateAndDelete();
    void plcNetworkRoundTrip();
    void clearAllAnswersAfterItsDelay();
    void resetGetsNoReply();
    void checksumsOffAndOn();
    void backupRestoreBackupIsIdentical();
    void benchmarkFillMakesALargeBackup();
    void restoreErrors_data();
    void restoreErrors();
    void restoreErasesAndStopsUntilTheClosingBlock();
};

void TestSimDevice::searchWalksTheTrackWithFlags() {
    auto line = demoLine();
    SimTestClient pc(*line);
    // Demo program 0, output 2: 0..45, 90..135, 180..225, 270..315.
    ReplyMatch r = pc.call(kQuery, "NF", track(0, 2));
    QCOMPARE(r.kind, ReplyMatch::Matches);
    QCOMPARE(r.fields.num("on"), 0);
    QCOMPARE(r.fields.num("off"), 45);
    QCOMPARE(r.fields.num("more"), 1);

    r = pc.call(kQuery, "NN");
    QCOMPARE(r.fields.num("on"), 90);
    QCOMPARE(r.fields.num("earlier"), 1);
    QCOMPARE(r.fields.num("more"), 1);
    pc.call(kQuery, "NN");
    r = pc.call(kQuery, "NN");
    QCOMPARE(r.fields.num("on"), 270);
    QCOMPARE(r.fields.num("earlier"), 1);
    QCOMPARE(r.fields.num("more"), 0);

    r = pc.call(kQuery, "NN");  // past the end
    QCOMPARE(r.fields.num("on"), kNoCam);
    QCOMPARE(r.fields.num("off"), kNoCam);
    r = pc.call(kQuery, "NP");  // back onto the last cam
    QCOMPARE(r.fields.num("on"), 270);

    r = pc.call(kQuery, "NL");
    QCOMPARE(r.fields.num("on"), 270);
    QCOMPARE(r.fields.num("earlier"), 1);

    r = pc.call(kQuery, "NS", Fields().set("on", 100));
    QCOMPARE(r.fields.num("on"), 180);
    QCOMPARE(r.fields.num("earlier"), 1);
    QCOMPARE(r.fields.num("more"), 1);

    pc.call(kQuery, "NF", track(0, 2));
    r = pc.call(kQuery, "NP");  // before the first
    QCOMPARE(r.fields.num("on"), kNoCam);
    QCOMPARE(r.fields.num("earlier"), 0);
    QCOMPARE(r.fields.num("more"), 1);
}

void TestSimDevice::emptyTrackAnswersNoCam() {
    auto line = demoLine();
    SimTestClient pc(*line);
    ReplyMatch r = pc.call(kQuery, "NF", track(5, 7));
    QCOMPARE(r.kind, ReplyMatch::Matches);
    QCOMPARE(r.fields.num("on"), kNoCam);
    QCOMPARE(r.fields.num("off"), kNoCam);
    QCOMPARE(r.fields.num("more"), 0);
    r = pc.call(kQuery, "NL");
    QCOMPARE(r.fields.num("on"), kNoCam);
    QCOMPARE(r.fields.num("earlier"), 0);
}

void TestSimDevice::searchWithoutSelectedTrackIsAnError() {
    auto line = demoLine();
    SimTestClient pc(*line);
    QCOMPARE(pc.call(kQuery, "NN").kind, ReplyMatch::DeviceError);
    const ReplyMatch r = pc.call(kQuery, "NF", track(0, 99));  // no output 99 on 32 outputs
    QCOMPARE(r.kind, ReplyMatch::DeviceError);
    QCOMPARE(r.errorCode, -1);
}

void TestSimDevice::insertRejectsOverlapAndRange() {
    auto line = demoLine();
    SimTestClient pc(*line);
    QCOMPARE(pc.call(kCommand, "NINS", cam(3, 0, 100, 200)).kind, ReplyMatch::Matches);
    QCOMPARE(pc.call(kCommand, "NINS", cam(3, 0, 150, 250)).errorCode, -1);  // overlaps
    QCOMPARE(pc.call(kCommand, "NINS", cam(3, 0, 50, 101)).errorCode, -1);   // overlaps the start
    QCOMPARE(pc.call(kCommand, "NINS", cam(3, 0, 300, 360)).errorCode, -1);  // beyond ?IMAX 359
    QCOMPARE(pc.call(kCommand, "NINS", cam(3, 0, 300, 300)).errorCode, -1);  // empty
    QCOMPARE(pc.call(kCommand, "NINS", cam(3, 0, 350, 120)).errorCode, -1);  // wraps into 100..200
    QCOMPARE(pc.call(kCommand, "NINS", cam(3, 0, 350, 100)).kind,
             ReplyMatch::Matches);  // wraps, touches
    QCOMPARE(pc.call(kCommand, "NINS", cam(3, 0, 200, 210)).kind,
             ReplyMatch::Matches);                                       // touches the end
    QCOMPARE(pc.call(kCommand, "NINS", cam(3, 0, 5, 6)).errorCode, -1);  // inside the wrapping cam

    ReplyMatch r = pc.call(kQuery, "NF", track(3, 0));
    QCOMPARE(r.fields.num("on"), 100);
    r = pc.call(kQuery, "NN");
    QCOMPARE(r.fields.num("on"), 200);
    r = pc.call(kQuery, "NN");
    QCOMPARE(r.fields.num("on"), 350);
    QCOMPARE(r.fields.num("off"), 100);
    QCOMPARE(r.fields.num("more"), 0);
}

void TestSimDevice::deleteAndChangeNeedAnExistingCam() {
    auto line = demoLine();
    SimTestClient pc(*line);
    QCOMPARE(pc.call(kCommand, "NDEL", track(0, 0).set("on", 11)).errorCode, -1);
    QCOMPARE(pc.call(kCommand, "NDEL", track(0, 0).set("on", 10)).kind, ReplyMatch::Matches);
    QCOMPARE(pc.call(kCommand, "NDEL", track(0, 0).set("on", 10)).errorCode, -1);

    QCOMPARE(pc.call(kCommand, "NC", cam(0, 0, 20, 30).set("oldOn", 999)).errorCode, -1);
    QCOMPARE(pc.call(kCommand, "NC", cam(0, 0, 20, 30).set("oldOn", 180)).kind,
             ReplyMatch::Matches);
    const ReplyMatch r = pc.call(kQuery, "NF", track(0, 0));
    QCOMPARE(r.fields.num("on"), 20);
    QCOMPARE(r.fields.num("off"), 30);
    QCOMPARE(r.fields.num("more"), 0);
}

void TestSimDevice::programAndTrackCopies() {
    auto line = demoLine();
    SimTestClient pc(*line);
    const SimCamStore& cams = line->device(0)->state().cams;
    QCOMPARE(pc.call(kCommand, "PCPY", Fields().set("target", 9).set("source", 0)).kind,
             ReplyMatch::Matches);
    QCOMPARE(cams.programs().value(9), cams.programs().value(0));
    QCOMPARE(
        pc.call(kCommand, "PACPY", Fields().set("program", 9).set("target", 7).set("source", 2))
            .kind,
        ReplyMatch::Matches);
    QCOMPARE(cams.track(9, 7), cams.track(0, 2));
    QCOMPARE(pc.call(kCommand, "PDEL", Fields().set("program", 9)).kind, ReplyMatch::Matches);
    QVERIFY(!cams.programs().contains(9));
    QCOMPARE(pc.call(kCommand, "PDEL", Fields().set("program", 16)).errorCode, -1);
    QCOMPARE(pc.call(kCommand, "PT", Fields().set("program", 4).set("type", 1)).kind,
             ReplyMatch::Matches);
    QCOMPARE(cams.track(4, 31), (QList<cambench::Cam>{{0, 179}}));
}

void TestSimDevice::deadTimeAboveMaximumIsRejected() {
    auto line = demoLine();
    SimTestClient pc(*line);
    ReplyMatch r = pc.call(kCommand, "TZK", Fields().set("output", 4).set("value", 10000));
    QCOMPARE(r.kind, ReplyMatch::DeviceError);
    QCOMPARE(r.errorCode, -12);
    QCOMPARE(pc.call(kCommand, "TZK", Fields().set("output", 4).set("value", 9999)).kind,
             ReplyMatch::Matches);
    r = pc.call(kQuery, "TZK", Fields().set("output", 4));
    QCOMPARE(r.fields.num("output"), 4);
    QCOMPARE(r.fields.num("value"), 9999);
}

void TestSimDevice::unknownCommandGetsNotUnderstood() {
    auto line = demoLine();
    SimTestClient pc(*line);
    const QList<Frame> frames = pc.replies(line->feed(pc.rawRequest(kQuery, "XYZ", 0)));
    QCOMPARE(frames.size(), 1);
    QCOMPARE(frames.first().body, QByteArray("Z11.10.1994", 11) + '\0');
}

void TestSimDevice::settingsKeepValuesAndCheckRanges() {
    auto line = demoLine();
    SimTestClient pc(*line);
    QCOMPARE(pc.call(kQuery, "IMUL").fields.num("value"), 1);
    QCOMPARE(pc.call(kCommand, "GISTHYS", Fields().set("value", 126)).errorCode, -1);
    QCOMPARE(pc.call(kCommand, "GISTHYS", Fields().set("value", 12)).kind, ReplyMatch::Matches);
    QCOMPARE(pc.call(kQuery, "GISTHYS").fields.num("value"), 12);
    QCOMPARE(pc.call(kCommand, "AMAX", Fields().set("value", 12)).errorCode,
             -1);  // not a multiple of 8
    QCOMPARE(pc.call(kCommand, "IMUL", Fields().set("value", 0)).errorCode, -1);
    QCOMPARE(pc.call(kCommand, "IMUL", Fields().set("value", -5)).kind, ReplyMatch::Matches);
    QCOMPARE(pc.call(kQuery, "IMUL").fields.num("value"), -5);
    QCOMPARE(pc.call(kCommand, "IFOR", Fields().setBytes("text", "##.##")).kind,
             ReplyMatch::Matches);
    QCOMPARE(pc.call(kQuery, "IFOR").fields.bytes("text"), QByteArray("##.##"));
    QCOMPARE(pc.call(kQuery, "GPRGMAX").fields.num("value"), 16);
    QCOMPARE(pc.call(kQuery, "IMAX").fields.num("value"), 359);

    Fields mode;
    mode.set("channel", 3).set("minimum", -100).set("maximum", 100).setBytes("format", "###");
    mode.set("gain", 2).set("offset", -32000);
    QCOMPARE(pc.call(kCommand, "AMODE", mode).kind, ReplyMatch::Matches);
    const ReplyMatch r = pc.call(kQuery, "AMODE", Fields().set("channel", 3));
    QCOMPARE(r.fields.num("minimum"), -100);
    QCOMPARE(r.fields.bytes("format"), QByteArray("###"));
    QCOMPARE(pc.call(kQuery, "AMODE", Fields().set("channel", 2)).fields.num("minimum"), 0);
    QCOMPARE(pc.call(kQuery, "AMODE", Fields().set("channel", 14)).errorCode, -1);
}

void TestSimDevice::specialEncoderPageSetsTextsAndType() {
    auto line = demoLine();
    SimTestClient pc(*line);
    Fields page;
    page.setBytes("text1", "My SSI").setBytes("text2", "25 bit").set("type", 2);
    page.set("resolutionBits", 25).set("firstBit", 1).set("capping", 0).set("errorBit", 26);
    QCOMPARE(pc.call(kCommand, "GSSSI", page).kind, ReplyMatch::Matches);
    QCOMPARE(pc.call(kQuery, "GSSSI").fields.num("resolutionBits"), 25);
    QCOMPARE(pc.call(kQuery, "GTXT1").fields.bytes("text"), QByteArray("My SSI"));
    QCOMPARE(pc.call(kQuery, "GTXT2").fields.bytes("text"), QByteArray("25 bit"));
    QCOMPARE(pc.call(kQuery, "GSTYP").fields.num("value"), 2);
    QCOMPARE(pc.call(kQuery, "GEBER").fields.num("value"), 0xFF);
}

void TestSimDevice::usersWalkCreateAndDelete() {
    auto line = demoLine();
    SimTestClient pc(*line);
    QCOMPARE(pc.call(kQuery, "USER", Fields().set("index", 0)).fields.bytes("name"),
             QByteArray("Supervisor"));
    QCOMPARE(pc.call(kQuery, "USER", Fields().set("index", 1)).fields.bytes("name"),
             QByteArray("Operator"));
    ReplyMatch end = pc.call(kQuery, "USER", Fields().set("index", 1));
    QCOMPARE(end.kind, ReplyMatch::Matches);
    QVERIFY(end.fields.bytes("name").isEmpty());
    QVERIFY(end.fields.bytes("number").isEmpty());

    Fields user;
    user.setBytes("name", "Setter")
        .setBytes("number", "777")
        .setBytes("access", QByteArray(32, '\x0F'));
    user.set("rights", 0x03);
    QCOMPARE(pc.call(kCommand, "USER", user).kind, ReplyMatch::Matches);
    QCOMPARE(pc.call(kCommand, "USER", user).errorCode, -1);  // number in use
    user.setBytes("oldNumber", "777").setBytes("name", "Setter 2");
    QCOMPARE(pc.call(kCommand, "USER", user).kind, ReplyMatch::Matches);
    QCOMPARE(line->device(0)->state().users.last().name, QByteArray("Setter 2"));
    user.setBytes("number", "DEL");
    QCOMPARE(pc.call(kCommand, "USER", user).kind, ReplyMatch::Matches);
    QCOMPARE(line->device(0)->state().users.size(), 2);
    QCOMPARE(pc.call(kCommand, "USER", user).errorCode, -1);  // already gone
}

void TestSimDevice::plcNetworkRoundTrip() {
    auto line = demoLine();
    SimTestClient pc(*line);
    QList<qint64> symbols(30, 0);
    symbols[0] = 0x0105;
    symbols[29] = 0x0B07;
    Fields network;
    network.set("area", 0x0B)
        .set("number", 3)
        .set("value", 42)
        .set("reset", 0x0102)
        .setWords("symbols", symbols);
    QCOMPARE(pc.call(kCommand, "GMXSPS", network).kind, ReplyMatch::Matches);
    const ReplyMatch r = pc.call(kQuery, "GMXSPS", Fields().set("area", 0x0B).set("number", 3));
    QCOMPARE(r.fields.words("symbols"), symbols);
    QCOMPARE(r.fields.num("reset"), 0x0102);
    QCOMPARE(
        pc.call(kQuery, "SPSSOLL", Fields().set("area", 0x0B).set("number", 3)).fields.num("value"),
        42);
    QCOMPARE(
        pc.call(kCommand, "SPSIST", Fields().set("area", 0x0B).set("number", 3).set("value", 7))
            .kind,
        ReplyMatch::Matches);
    QCOMPARE(
        pc.call(kQuery, "SPSIST", Fields().set("area", 0x0B).set("number", 3)).fields.num("value"),
        7);
    QCOMPARE(pc.call(kQuery, "GMXSPS", Fields().set("area", 0x07).set("number", 0)).errorCode, -1);
}

void TestSimDevice::clearAllAnswersAfterItsDelay() {
    SimProfile profile;
    profile.clearDelayMs = 777;
    auto line = demoLine(profile);
    SimTestClient pc(*line);
    const QList<SimOutput> out = line->feed(pc.requestBytes(kCommand, "CA", {}, 0));
    QCOMPARE(out.size(), 1);
    QCOMPARE(out.first().delayMs, profile.processingDelayMs + 777);
    QCOMPARE(line->device(0)->state().cams.camCount(), 0);
    QCOMPARE(pc.call(kQuery, "MEENOCK").fields.num("value"), 0);
}

void TestSimDevice::resetGetsNoReply() {
    auto line = demoLine();
    SimTestClient pc(*line);
    QVERIFY(line->feed(pc.requestBytes(kCommand, "GRESET", {}, 0)).isEmpty());
    QCOMPARE(line->device(0)->executions(), 1);
}

void TestSimDevice::checksumsOffAndOn() {
    auto line = demoLine();
    SimTestClient pc(*line);
    QList<Frame> frames = pc.replies(line->feed("!C0\r\n"));
    QCOMPARE(frames.size(), 1);
    QCOMPARE(frames.first().body, QByteArray("C0OK"));
    QVERIFY(!line->device(0)->checksumsEnabled());
    const QList<SimOutput> out = line->feed("?EPROM\r\n");
    QCOMPARE(out.size(), 1);
    QCOMPARE(out.first().bytes, QByteArray(":EPROM11.10.1994", 16) + QByteArray("\0\r\n", 3));
    line->feed("!C1\r\n");
    QVERIFY(line->device(0)->checksumsEnabled());
}

void TestSimDevice::backupRestoreBackupIsIdentical() {
    auto source = demoLine();
    SimTestClient pc(*source);
    pc.call(kCommand, "IFOR", Fields().setBytes("text", "#.###"));
    pc.call(kCommand, "BTXT", Fields().set("line", 3).setBytes("text", "line three"));
    pc.call(kCommand, "ETXT",
            Fields().set("message", 2).setBytes("text1", "Oil low").setBytes("text4", "call 99"));
    pc.call(kCommand, "PAU", Fields().set("value", 2));
    fillBenchmarkCams(*source->device(0), 3);
    const QList<QByteArray> first = pc.backup();
    QVERIFY(first.size() > 100);
    QCOMPARE(first.first().size(), 128);

    SimLine target(Framing::Standard);
    target.addDevice(std::make_unique<SimDevice>());
    SimTestClient writer(target);
    for (int i = 0; i < first.size(); ++i)
        QCOMPARE(writer.writeBlock(i, first.at(i)).kind, ReplyMatch::Matches);
    QCOMPARE(writer.writeBlock(int(first.size()), {}).kind, ReplyMatch::Matches);

    QVERIFY(target.device(0)->state() == source->device(0)->state());
    QCOMPARE(writer.backup(), first);
    QCOMPARE(writer.call(kQuery, "PAU").fields.num("value"), 2);
    QCOMPARE(writer.call(kQuery, "ETXT", Fields().set("message", 2)).fields.bytes("text4"),
             QByteArray("call 99"));
}

void TestSimDevice::benchmarkFillMakesALargeBackup() {
    SimPortConfig config;
    config.fill = 8;
    auto line = makeSimLine(config);
    QCOMPARE(line->device(0)->state().cams.camCount(), 16 * 32 * 8);
    qint64 bytes = 0;
    for (const QByteArray& block : SimTestClient(*line).backup()) bytes += block.size();
    QVERIFY2(bytes >= 32 * 1024, qPrintable(QString::number(bytes)));
}

void TestSimDevice::restoreErrors_data() {
    QTest::addColumn<int>("expected");
    QTest::addColumn<bool>("eraseFails");
    QTest::addColumn<QList<int>>("numbers");  // block numbers sent; the last one's reply is checked
    QTest::addColumn<QList<QByteArray>>("data");

    const QByteArray basic = sim_eeprom::serialize(SimState(), SimProfile()).first();
    const QByteArray record =
        sim_eeprom::serialize(defaultState(SimProfile(), 0), SimProfile()).at(1);
    QByteArray badMagic = basic;
    badMagic[0] = 'X';
    QByteArray shortRecord = record;
    shortRecord.chop(1);
    QTest::newRow("-41 block 0 not 128 bytes")
        << -41 << false << QList<int>{0} << QList<QByteArray>{basic.left(100)};
    QTest::newRow("-42 erase impossible")
        << -42 << true << QList<int>{0} << QList<QByteArray>{basic};
    QTest::newRow("-43 block skipped")
        << -43 << false << QList<int>{0, 2} << QList<QByteArray>{basic, record};
    QTest::newRow("-43 block repeated")
        << -43 << false << QList<int>{0, 1, 1} << QList<QByteArray>{basic, record, record};
    QTest::newRow("-44 cannot start")
        << -44 << false << QList<int>{0, 1} << QList<QByteArray>{badMagic, {}};
    QTest::newRow("-45 length disagrees")
        << -45 << false << QList<int>{0, 1} << QList<QByteArray>{basic, shortRecord};
    QTest::newRow("-45 nibble zero")
        << -45 << false << QList<int>{0, 1} << QList<QByteArray>{basic, QByteArray(6, '\x07')};
    QTest::newRow("-46 no block 0") << -46 << false << QList<int>{1} << QList<QByteArray>{record};
}

void TestSimDevice::restoreErrors() {
    QFETCH(int, expected);
    QFETCH(bool, eraseFails);
    QFETCH(QList<int>, numbers);
    QFETCH(QList<QByteArray>, data);
    SimProfile profile;
    profile.eraseFails = eraseFails;
    SimLine line(Framing::Standard);
    line.addDevice(std::make_unique<SimDevice>(profile));
    SimTestClient pc(line);
    ReplyMatch reply;
    for (int i = 0; i < numbers.size(); ++i) {
        reply = pc.writeBlock(numbers.at(i), data.at(i));
        if (i + 1 < numbers.size()) QCOMPARE(reply.kind, ReplyMatch::Matches);
    }
    QCOMPARE(reply.kind, ReplyMatch::DeviceError);
    QCOMPARE(reply.errorCode, expected);
}

void TestSimDevice::restoreErasesAndStopsUntilTheClosingBlock() {
    auto line = demoLine();
    SimTestClient pc(*line);
    const QList<QByteArray> blocks = pc.backup();
    QCOMPARE(pc.writeBlock(0, blocks.first()).kind, ReplyMatch::Matches);
    QCOMPARE(pc.call(kQuery, "MEENOCK").fields.num("value"), 0);
    QVERIFY(!line->device(0)->axis().running());
    for (int i = 1; i < blocks.size(); ++i)
        QCOMPARE(pc.writeBlock(i, blocks.at(i)).kind, ReplyMatch::Matches);
    QCOMPARE(pc.writeBlock(int(blocks.size()), {}).kind, ReplyMatch::Matches);
    QVERIFY(line->device(0)->axis().running());
    QCOMPARE(pc.call(kQuery, "MEENOCK").fields.num("value"), 11);
}

QTEST_GUILESS_MAIN(TestSimDevice)
#include "tst_sim_device.moc"
