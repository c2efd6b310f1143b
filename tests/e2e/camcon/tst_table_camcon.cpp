// TableCamCon (3964R/RK512 and the short commands) over a pseudo-terminal
// with the real QSerialPort against the real cambench-sim, for both
// variants: cams up to the variant's reach, dead-time modes, settings,
// status, PLC links, short commands, and link faults at 1 %.
#include "../sim_process.h"

#include "comm/camcon/table/cam_track_words.h"
#include "comm/camcon/table/frame_3964r.h"
#include "comm/camcon/table/short_commands.h"
#include "comm/camcon/table/table_camcon.h"
#include "comm/camcon/usecases/read_everything.h"
#include "comm/camcon/usecases/write_items.h"
#include "comm/device/protocol_registry.h"
#include "comm/transport/transport_registry.h"
#include "model/camcon/cam_validation.h"

#include <QLoggingCategory>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace cambench;
using namespace cambench::comm;
using namespace cambench::comm::table;
using cambench::e2e::SimProcess;

namespace {

const QString kBaud = QStringLiteral("115200");

// One simulator process and the device on top of the PC's serial port.
struct Bench {
    QTemporaryDir dir;
    SimProcess sim;
    std::unique_ptr<Transport> transport;
    std::unique_ptr<TableCamCon> device;
    int stxSent = 0;              // STX the PC sent: more than requests when faults made it repeat
    QMap<int, int> writesToArea;  // RK512 write telegrams ('A') the PC sent, by data area

    bool start(const QString& protocol, const QStringList& simArgs = {}) {
        if (!sim.start(QStringList{QStringLiteral("--protocol"), protocol, QStringLiteral("--baud"),
                                   kBaud} +
                           simArgs,
                       dir.filePath(QStringLiteral("sim.log"))))
            return false;
        const ProtocolInfo* info = ProtocolRegistry::instance().find(protocol);
        ConnectionSettings connection;
        connection.port = sim.ptyPath();
        connection.serial = info->defaultSerial;
        connection.serial.baud = kBaud.toInt();
        connection.protocol = protocol;
        Result<std::unique_ptr<Transport>> made = makeTransport(connection);
        if (!made || !(*made)->open()) return false;
        transport = std::move(made).value();
        TableSettings settings;
        settings.variant =
            protocol == QLatin1String("3964r-e38") ? Rk512Variant::E38 : Rk512Variant::N96;
        device =
            std::make_unique<TableCamCon>(*transport, settings, lineTimingFor(connection.serial));
        device->engine().setTrafficSink([this](const TrafficEntry& entry) {
            // An STX alone, or after the DLE that acknowledged a telegram.
            if (entry.outgoing && entry.bytes.size() <= 2 && entry.bytes.endsWith(kStx)) ++stxSent;
            const QByteArray& t = entry.bytes;
            if (entry.outgoing && t.size() > 4 && t.at(0) == 0 && t.at(1) == 0 &&
                quint8(t.at(2)) == quint8(Rk512Order::Write))
                ++writesToArea[quint8(t.at(4))];
        });
        return true;
    }
    bool n96() const { return device->link().variant() == Rk512Variant::N96; }
};

#define START(bench, ...) QVERIFY2((bench).start(__VA_ARGS__), qPrintable((bench).sim.errorText()))
#define VERIFY_OK(result) QVERIFY2((result).ok(), qPrintable((result).error().message))

void variantRows() {
    QTest::addColumn<QString>("protocol");
    QTest::newRow("n96") << QStringLiteral("3964r-n96");
    QTest::newRow("e38") << QStringLiteral("3964r-e38");
}

// `count` cams over 0..359: the first wraps through zero, the others are
// 2 units apart behind it.
QList<Cam> manyCams(int count) {
    QList<Cam> cams{{350, 2}};
    for (int i = 0; i + 1 < count; ++i) cams.append({qint32(2 + 2 * i), qint32(3 + 2 * i)});
    return cams;
}

Track sorted(Track track) {
    normaliseTrack(track);
    return track;
}

}  // namespace

class TestTableCamCon : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { QLoggingCategory::setFilterRules(QStringLiteral("cambench.*=false")); }
    void identityAndStatus_data() { variantRows(); }
    void identityAndStatus();
    void fullestTrackWithAWrappingCamRoundTrips_data() { variantRows(); }
    void fullestTrackWithAWrappingCamRoundTrips();
    void rewriteLeavesExactlyTheNewCams_data() { variantRows(); }
    void rewriteLeavesExactlyTheNewCams();
    void deadTimesAndModes_data() { variantRows(); }
    void deadTimesAndModes();
    void settingsAndSpecialEncoderRoundTrip_data() { variantRows(); }
    void settingsAndSpecialEncoderRoundTrip();
    void programChangeAndErrorReset_data() { variantRows(); }
    void programChangeAndErrorReset();
    void plcLinksAndValuesRoundTrip_data() { variantRows(); }
    void plcLinksAndValuesRoundTrip();
    void shortCommandsAgreeWithTheTable_data() { variantRows(); }
    void shortCommandsAgreeWithTheTable();
    void analogueCamsLockAndProgrammingProgram_data() { variantRows(); }
    void analogueCamsLockAndProgrammingProgram();
    void linkFaultsAtOnePercentGiveRightResults_data() { variantRows(); }
    void linkFaultsAtOnePercentGiveRightResults();
    void projectsWithAndWithoutAnalogueOutputs();
};

void TestTableCamCon::identityAndStatus() {
    QFETCH(QString, protocol);
    Bench bench;
    START(bench, protocol);
    const Result<DeviceInfo> info = bench.device->readInfo();
    VERIFY_OK(info);
    QCOMPARE(info->epromDate, QStringLiteral("11.10.1994"));
    QCOMPARE(info->outputs, 32);
    QCOMPARE(info->programs, 16);
    QCOMPARE(info->maxPosition, 359);
    QCOMPARE(info->protocol, 4);
    const Result<DeviceStatus> status = bench.device->readStatus(32, 16);
    VERIFY_OK(status);
    QCOMPARE(status->activeProgram, 0);
    QCOMPARE(status->errorState, 0);
    QCOMPARE(status->outputs.size(), 32);
    QCOMPARE(status->inputs.size(), 16);
    QVERIFY(status->inputs.first());  // input 1: the axis runs
}

void TestTableCamCon::fullestTrackWithAWrappingCamRoundTrips() {
    QFETCH(QString, protocol);
    Bench bench;
    START(bench, protocol);
    // n96 reaches all 125 places; e38 the places 1..63 of words 0..127, of
    // which one stays empty so that a read can tell where the track ends.
    const int reach = bench.n96() ? kMaxTrackCams : 62;
    const Track track{5, manyCams(reach)};
    VERIFY_OK(bench.device->writeTrack(3, track));
    const Result<Track> read = bench.device->readTrack(3, 5);
    VERIFY_OK(read);
    QCOMPARE(read->cams.size(), qsizetype(reach));
    QCOMPARE(*read, sorted(track));
    // Other programs and tracks are untouched.
    const Result<Track> other = bench.device->readTrack(0, 1);
    VERIFY_OK(other);
    QCOMPARE(other->cams, (QList<Cam>{{10, 90}, {180, 270}}));
    const Status tooMany = bench.device->writeTrack(3, Track{6, manyCams(reach + 1)});
    QVERIFY(!tooMany.ok());
    QCOMPARE(tooMany.error().kind, bench.n96() ? ErrorKind::InvalidData : ErrorKind::Usage);
}

void TestTableCamCon::rewriteLeavesExactlyTheNewCams() {
    QFETCH(QString, protocol);
    Bench bench;
    START(bench, protocol);
    // 40 cams need two telegrams; the rewrite with 3 must leave only those.
    VERIFY_OK(bench.device->writeTrack(1, Track{7, manyCams(40)}));
    const Track fewer{7, {{300, 20}, {100, 120}, {30, 40}}};
    VERIFY_OK(bench.device->writeTrack(1, fewer));
    Result<Track> read = bench.device->readTrack(1, 7);
    VERIFY_OK(read);
    QCOMPARE(*read, sorted(fewer));
    for (const Track& small : {Track{7, {{5, 6}}}, Track{7, {}}}) {
        VERIFY_OK(bench.device->writeTrack(1, small));
        read = bench.device->readTrack(1, 7);
        VERIFY_OK(read);
        QCOMPARE(*read, small);
    }
    // An overlap is refused by the device with RK512 error 54.
    const Status overlap = bench.device->writeTrack(1, Track{7, {{10, 50}, {40, 60}}});
    QVERIFY(!overlap.ok());
    QCOMPARE(overlap.error().kind, ErrorKind::DeviceError);
    QCOMPARE(overlap.error().deviceCode, 54);
}

void TestTableCamCon::deadTimesAndModes() {
    QFETCH(QString, protocol);
    Bench bench;
    START(bench, protocol);
    VERIFY_OK(bench.device->writeDeadTime(5, 321));
    const Result<DeadTimes> deadTimes = bench.device->readDeadTimes(6);
    VERIFY_OK(deadTimes);
    QCOMPARE(deadTimes->value(1), 25);
    QCOMPARE(deadTimes->value(5), 321);
    QCOMPARE(bench.device->has(CamConCapability::DeadTimeModes), bench.n96());
    if (!bench.n96()) {
        const Result<DeadTimeModes> modes = bench.device->readDeadTimeModes(2);
        QCOMPARE(modes.error().kind, ErrorKind::Unsupported);
        QVERIFY2(modes.error().message.contains(QLatin1String("3964r-n96")),
                 qPrintable(modes.error().message));
        return;
    }
    Result<DeadTimeModes> modes = bench.device->readDeadTimeModes(3);
    VERIFY_OK(modes);
    QCOMPARE(modes->value(2), (OutputDeadTime{DeadTimeMode::SeparateOnOff, 120, 80, 150}));
    QCOMPARE(modes->value(1).mode, DeadTimeMode::Normal);
    const OutputDeadTime pathTime{DeadTimeMode::PathTime, 40, 12, 900};
    VERIFY_OK(bench.device->writeDeadTimeMode(3, pathTime));
    modes = bench.device->readDeadTimeModes(3);
    VERIFY_OK(modes);
    QCOMPARE(modes->value(3), pathTime);
    const Status tooLong =
        bench.device->writeDeadTimeMode(3, {DeadTimeMode::SeparateOnOff, 0, 10000, 0});
    QCOMPARE(tooLong.error().deviceCode, 54);
}

void TestTableCamCon::settingsAndSpecialEncoderRoundTrip() {
    QFETCH(QString, protocol);
    Bench bench;
    START(bench, protocol);
    QStringList skipped;
    const Result<SystemSettings> before = bench.device->readSettings(&skipped);
    VERIFY_OK(before);
    QCOMPARE(before->value(QStringLiteral("encoderType")).toLongLong(), 1);
    QCOMPARE(before->value(QStringLiteral("outputCount")).toLongLong(), 32);
    QCOMPARE(before->value(QStringLiteral("speedFactor")).toLongLong(), 100000);
    QVERIFY(!before->contains(QStringLiteral("encoderText1")));
    QVERIFY2(skipped.join(u' ').contains(QLatin1String("Encoder text line 1")),
             qPrintable(skipped.join(u' ')));

    SystemSettings wanted{{QStringLiteral("cableLength"), 77},
                          {QStringLiteral("targetCycleTime"), 25},
                          {QStringLiteral("specialEncoder.timer.stepMs"), 3},
                          {QStringLiteral("specialEncoder.timer.resolution"), 3600}};
    VERIFY_OK(bench.device->writeSettings(wanted, *before));
    const Result<SystemSettings> after = bench.device->readSettings();
    VERIFY_OK(after);
    QCOMPARE(after->value(QStringLiteral("cableLength")).toLongLong(), 77);
    QCOMPARE(after->value(QStringLiteral("targetCycleTime")).toLongLong(), 25);
    QCOMPARE(after->value(QStringLiteral("encoderType")).toLongLong(), 0xFF);
    QCOMPARE(after->value(QStringLiteral("specialEncoder.type")).toLongLong(), 5);
    QCOMPARE(after->value(QStringLiteral("specialEncoder.timer.resolution")).toLongLong(), 3600);
    QCOMPARE(after->value(QStringLiteral("specialEncoder.timer.stepMs")).toLongLong(), 3);
    const Result<QVariant> one = bench.device->readSetting(QStringLiteral("axisType"));
    VERIFY_OK(one);
    QCOMPARE(one->toLongLong(), 0);

    // Out of range: the device refuses; a key without a data word: nothing written.
    QCOMPARE(bench.device->writeSettings({{QStringLiteral("cableLength"), 5000}}, *after)
                 .error()
                 .deviceCode,
             54);
    const Status text =
        bench.device->writeSettings({{QStringLiteral("speedFormat"), QStringLiteral("##.#")},
                                     {QStringLiteral("cableLength"), 12}},
                                    *after);
    QCOMPARE(text.error().kind, ErrorKind::InvalidData);
    QCOMPARE(bench.device->readSetting(QStringLiteral("cableLength"))->toLongLong(), 77);
}

void TestTableCamCon::programChangeAndErrorReset() {
    QFETCH(QString, protocol);
    Bench bench;
    START(bench, protocol);
    VERIFY_OK(bench.device->selectProgram(2));
    Result<DeviceStatus> status = bench.device->readStatus(32, 16);
    VERIFY_OK(status);
    QCOMPARE(status->activeProgram, 2);
    const Status refused = bench.device->selectProgram(99);
    QCOMPARE(refused.error().kind, ErrorKind::DeviceError);
    VERIFY_OK(bench.device->resetError());
    // The programming program is not the active program.
    VERIFY_OK(bench.device->writeProgrammingProgram({1, 0, 0}));
    status = bench.device->readStatus(32, 16);
    QCOMPARE(status->activeProgram, 2);
}

void TestTableCamCon::plcLinksAndValuesRoundTrip() {
    QFETCH(QString, protocol);
    Bench bench;
    START(bench, protocol);
    Result<PlcNetwork> timer = bench.device->readPlcNetwork(PlcNetwork::M, 4);
    VERIFY_OK(timer);
    QCOMPARE(timer->value, 500);
    QCOMPARE(timer->symbols[0], quint16(0x0103));
    QCOMPARE(*bench.device->readPlcActual(PlcNetwork::M, 4), 120);
    PlcNetwork network;
    network.area = PlcNetwork::X;
    network.number = 7;
    network.value = 2500;
    network.reset = 0x0203;
    for (int i = 0; i < PlcNetwork::kSymbols; ++i) network.symbols[size_t(i)] = quint16(0x0100 + i);
    VERIFY_OK(bench.device->writePlcNetwork(network));
    const Result<PlcNetwork> read = bench.device->readPlcNetwork(PlcNetwork::X, 7);
    VERIFY_OK(read);
    QCOMPARE(*read, network);
    QCOMPARE(*bench.device->readPlcSetpoint(PlcNetwork::X, 7), 2500);
    // The AND gate of the demo is still there.
    QCOMPARE(bench.device->readPlcNetwork(PlcNetwork::O, 0)->symbols[1], quint16(0x0A02));
}

void TestTableCamCon::shortCommandsAgreeWithTheTable() {
    QFETCH(QString, protocol);
    Bench bench;
    START(bench, protocol);
    TableLink& link = bench.device->link();
    const auto call = [&](const Result<QByteArray>& request) {
        return link.shortCommand(*request, QStringLiteral("short command"), kMaxShortTelegramBytes,
                                 RetryPolicy::Idempotent);
    };
    // 0x04 reads what RK512 reads.
    Result<QByteArray> reply = call(encodeReadTrackRequest(0, 3));
    VERIFY_OK(reply);
    const Result<Track> shortTrack = decodeReadTrackReply(*reply, 0, 3);
    VERIFY_OK(shortTrack);
    QCOMPARE(*shortTrack, *bench.device->readTrack(0, 3));
    // 0x05 replaces tracks, RK512 sees them.
    const QList<Track> tracks{{7, {{11, 22}, {33, 44}}}, {8, {{350, 5}}}};
    reply = call(encodeWriteTracksRequest(4, tracks));
    VERIFY_OK(reply);
    VERIFY_OK(decodeAcknowledgement(ShortCommand::WriteTracks, *reply));
    QCOMPARE(*bench.device->readTrack(4, 7), tracks.at(0));
    QCOMPARE(*bench.device->readTrack(4, 8), tracks.at(1));
    // 0x07 / 0x06 and RK512 word 0 are the same dead time.
    reply = call(encodeWriteDeadTimeRequest(9, 456));
    VERIFY_OK(decodeAcknowledgement(ShortCommand::WriteDeadTime, *reply));
    QCOMPARE(bench.device->readDeadTimes(9)->value(9), 456);
    reply = call(encodeReadDeadTimeRequest(9));
    QCOMPARE(decodeReadDeadTimeReply(*reply, 9)->deadTime, 456);
    // 0x01 status, 0x03 program change (refused for a program that is not there).
    reply = call(encodeProgramChangeRequest(3));
    VERIFY_OK(decodeAcknowledgement(ShortCommand::ProgramChange, *reply));
    const Result<ShortStatus> status = decodeStatusReply(*call(encodeStatusRequest()));
    VERIFY_OK(status);
    QCOMPARE(status->program, 3);
    QCOMPARE(status->outputCount, 32);
    reply = call(encodeProgramChangeRequest(16));
    QCOMPARE(decodeAcknowledgement(ShortCommand::ProgramChange, *reply).error().kind,
             ErrorKind::DeviceError);
    // An unknown command is answered ":Z".
    reply = link.shortCommand(QByteArrayLiteral("?\x09"), QStringLiteral("0x09"), 8,
                              RetryPolicy::Idempotent);
    VERIFY_OK(reply);
    QCOMPARE(decodeAcknowledgement(ShortCommand(0x09), *reply).error().kind,
             ErrorKind::NotUnderstood);
}

void TestTableCamCon::analogueCamsLockAndProgrammingProgram() {
    QFETCH(QString, protocol);
    Bench bench;
    START(bench, protocol);
    Result<AnalogueCamTrack> analogue = bench.device->readAnalogueCams(1);
    VERIFY_OK(analogue);
    QCOMPARE(analogue->points.size(), 3);
    const AnalogueCamTrack curve{2, {{0, -1000}, {90, 32000}, {200, 0}, {300, 0}}};
    VERIFY_OK(bench.device->writeAnalogueCams(curve));
    analogue = bench.device->readAnalogueCams(2);
    VERIFY_OK(analogue);
    QCOMPARE(*analogue, curve);

    QCOMPARE(*bench.device->readEepromLock(), false);
    VERIFY_OK(bench.device->writeEepromLock(true));
    QCOMPARE(*bench.device->readEepromLock(), true);

    const ProgrammingProgram programming{5, 2, 180};
    VERIFY_OK(bench.device->writeProgrammingProgram(programming));
    QCOMPARE(*bench.device->readProgrammingProgram(), programming);
}

void TestTableCamCon::linkFaultsAtOnePercentGiveRightResults() {
    QFETCH(QString, protocol);
    Bench clean;
    START(clean, protocol);
    const Result<DeviceInfo> cleanInfo = clean.device->readInfo();
    VERIFY_OK(cleanInfo);

    Bench bench;
    START(bench, protocol,
          {QStringLiteral("--link-faults"), QStringLiteral("0.01"), QStringLiteral("--drop"),
           QStringLiteral("0.01"), QStringLiteral("--seed"), QStringLiteral("11")});
    Result<DeviceInfo> info = bench.device->readInfo();
    VERIFY_OK(info);
    QCOMPARE(*info, *cleanInfo);
    // A whole program of 32 tracks x 20 cams, written and read back.
    CamProgram program;
    program.number = 2;
    for (int output = 1; output <= 32; ++output) {
        Track track{output, {}};
        for (int i = 0; i < 20; ++i)
            track.cams.append({qint32(18 * i + output % 5), qint32(18 * i + 9)});
        VERIFY_OK(bench.device->writeTrack(2, track));
        program.tracks.insert(output, track);
    }
    const Result<CamProgram> read = bench.device->readProgram(2, 32);
    VERIFY_OK(read);
    QCOMPARE(read->tracks, program.tracks);
    for (int output = 1; output <= 8; ++output)
        VERIFY_OK(bench.device->writeDeadTime(output, 100 + output));
    const Result<DeadTimes> deadTimes = bench.device->readDeadTimes(8);
    VERIFY_OK(deadTimes);
    for (int output = 1; output <= 8; ++output) QCOMPARE(deadTimes->value(output), 100 + output);
    const Result<SystemSettings> settings = bench.device->readSettings();
    VERIFY_OK(settings);
    VERIFY_OK(bench.device->writeSettings({{QStringLiteral("cableLength"), 33}}, *settings));
    QCOMPARE(bench.device->readSetting(QStringLiteral("cableLength"))->toLongLong(), 33);
    const Result<PlcNetwork> network = bench.device->readPlcNetwork(PlcNetwork::M, 4);
    VERIFY_OK(network);
    QCOMPARE(network->value, 500);
    info = bench.device->readInfo();
    VERIFY_OK(info);
    // The demo's one cam of program 2 (output 6) made room for 20.
    QCOMPARE(info->programmedCams, cleanInfo->programmedCams - 1 + 32 * 20);
    // The faults did happen: the PC had to start transfers again.
    const RequestEngine::Stats& stats = bench.device->engine().stats();
    qInfo("%d requests, %d STX sent, %d engine retries", stats.requests, bench.stxSent,
          stats.retries);
    QVERIFY(bench.stxSent > stats.requests);
}

// Issue 29: the use cases on two CamCons that differ. The one without
// analogue outputs reads its project (no analogue cams, said so) and takes
// it back unchanged; the other's analogue base points written to it are
// not sent and say why, while everything else is written.
void TestTableCamCon::projectsWithAndWithoutAnalogueOutputs() {
    Bench full;
    START(full, QStringLiteral("3964r-n96"));
    Bench bare;
    START(bare, QStringLiteral("3964r-n96"),
          {QStringLiteral("--analogue-outputs"), QStringLiteral("0")});
    const Result<DeviceInfo> fullInfo = full.device->readInfo();
    VERIFY_OK(fullInfo);
    const Result<DeviceInfo> bareInfo = bare.device->readInfo();
    VERIFY_OK(bareInfo);

    const Result<usecases::ReadEverything> withAnalogue =
        usecases::readEverything(*full.device, *fullInfo);
    VERIFY_OK(withAnalogue);
    QCOMPARE(withAnalogue->project.analogueCams.size(), 14);
    QCOMPARE(withAnalogue->project.analogueCams.first().points.size(), 3);
    const Result<usecases::ReadEverything> without =
        usecases::readEverything(*bare.device, *bareInfo);
    VERIFY_OK(without);
    QVERIFY(without->project.analogueCams.isEmpty());
    QVERIFY2(
        without->skipped.join(QLatin1Char('\n')).contains(QLatin1String("no analogue outputs")),
        qPrintable(without->skipped.join(QLatin1Char('\n'))));

    const Result<ProgrammingProgram> programmingBefore = bare.device->readProgrammingProgram();
    VERIFY_OK(programmingBefore);
    bare.writesToArea.clear();
    const Result<usecases::WriteReport> back = usecases::writeItems(
        *bare.device, *bareInfo, usecases::planFromProject(without->project, without->project));
    VERIFY_OK(back);
    // Every item unchanged, the programming program too (issue 39: it was
    // "written" on every write of an unchanged project, as the cam reads
    // had selected their programs).
    QStringList changed;
    for (const usecases::OutcomeLine& item : back->lines()) {
        if (item.state != usecases::WriteState::Unchanged) changed << item.text;
    }
    QVERIFY(back->analogueCams.isEmpty());
    QVERIFY(back->programmingProgram.has_value());
    QVERIFY2(changed.isEmpty(), qPrintable(changed.join(QLatin1Char('\n'))));
    // The only write telegrams: to area 201, selecting each program whose
    // cams are read (the table interface reaches the cams of the
    // programming program only) and setting the programming program back
    // as it was. None wrote an item.
    QCOMPARE(bare.writesToArea.keys(), QList<int>{201});
    qInfo(
        "%d write telegrams to area 201 (program selections and setting it back) for %d "
        "programs",
        bare.writesToArea.value(201), int(without->project.programs.size()));
    QCOMPARE(*bare.device->readProgrammingProgram(), *programmingBefore);

    // The other device's analogue cams (and nothing else of its settings).
    Project analogueOnly;
    analogueOnly.analogueCams = withAnalogue->project.analogueCams;
    const Result<usecases::WriteReport> carried = usecases::writeItems(
        *bare.device, *bareInfo, usecases::planFromProject(analogueOnly, without->project));
    VERIFY_OK(carried);
    QCOMPARE(carried->analogueCams.size(), 14);
    QCOMPARE(carried->analogueCams.first().state, usecases::WriteState::NotSent);
    QVERIFY2(
        carried->analogueCams.first().error.message.contains(QLatin1String("no analogue outputs")),
        qPrintable(carried->analogueCams.first().error.message));
    QCOMPARE(carried->analogueCams.at(1).state, usecases::WriteState::Unchanged);
    QCOMPARE(carried->count(usecases::WriteState::Written), 0);
}

QTEST_GUILESS_MAIN(TestTableCamCon)
#include "tst_table_camcon.moc"
