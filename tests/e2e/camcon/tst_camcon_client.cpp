// The ASCII CamCon against the in-process simulator: no subprocess, no worker.
#include "comm/camcon/ascii/ascii_camcon.h"
#include "comm/camcon/ascii/ascii_link.h"
#include "comm/camcon/ascii/settings_commands.h"
#include "comm/sim/sim_transport.h"
#include "tests/usecases/camcon/sim_bench.h"

#include <QLoggingCategory>
#include <QSet>
#include <QTest>

#include <memory>

using namespace cambench;
using namespace cambench::comm;

namespace {

// A simulator line with the client on top; bytes arrive at once.
using Bench = cambench::tests::SimBench;

Track track(int output, QList<Cam> cams) {
    Track t;
    t.output = output;
    t.cams = std::move(cams);
    return t;
}

}  // namespace

class TestAsciiCamCon : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void readInfoReportsTheDeviceProfile();
    void writeTrackThenReadTrackGivesTheTarget();
    void writeTrackReplacesOverlappingCamsByDeletingFirst();
    void writeTrackLeavesEqualTrackUntouched();
    void outputOneIsProtocolOutputZero();
    void emptyTrackReadsAsNoCams();
    void readProgramListsOnlyTracksWithCams();
    void deadTimesAndNamesRoundTrip();
    void usersRoundTripAndDelete();
    void plcNetworkRoundTrip();
    void backupRestoreBringsBackTheState();
    void restoreFailureSaysTheDeviceIsErased();
    void scanBusFindsExactlyTheDevicesOnTheLine();
    void scanBusRestoresTheLinkSettings();
    void everyModelSettingHasACommand();
    void settingsWriteChangesOnlyWhatDiffers();
    void specialEncoderPageWriteSelectsItsType();
};

void TestAsciiCamCon::initTestCase() {
    // The scan's expected timeouts would flood the output.
    QLoggingCategory::setFilterRules(
        QStringLiteral("cambench.*.debug=false\n"
                       "cambench.comm.link.warning=false"));
}

void TestAsciiCamCon::readInfoReportsTheDeviceProfile() {
    Bench bench;
    const Result<DeviceInfo> info = bench.client->readInfo();
    QVERIFY2(info.ok(), qPrintable(info.error().message));
    const SimProfile& profile = bench.device().profile();
    QCOMPARE(info->epromDate, QString::fromLatin1(profile.epromDate));
    QCOMPARE(info->outputs, profile.outputs);
    QCOMPARE(info->inputs, profile.inputs);
    QCOMPARE(info->programs, profile.programs);
    QCOMPARE(info->minPosition, profile.minPosition);
    QCOMPARE(info->maxPosition, profile.maxPosition);
    QCOMPARE(info->maxDeadTime, profile.maxDeadTime);
}

void TestAsciiCamCon::writeTrackThenReadTrackGivesTheTarget() {
    Bench bench;
    const Track target = track(3, {{10, 20}, {100, 180}, {300, 350}});
    const Status written = bench.client->writeTrack(2, target);
    QVERIFY2(written.ok(), qPrintable(written.error().message));
    const Result<Track> read = bench.client->readTrack(2, 3);
    QVERIFY2(read.ok(), qPrintable(read.error().message));
    QCOMPARE(read->cams, target.cams);
}

void TestAsciiCamCon::writeTrackReplacesOverlappingCamsByDeletingFirst() {
    Bench bench;
    QVERIFY(bench.client->writeTrack(1, track(4, {{10, 60}, {200, 250}})).ok());
    // Each new cam overlaps an old one: inserting before deleting would fail.
    const Track target = track(4, {{50, 120}, {240, 300}});
    const Status written = bench.client->writeTrack(1, target);
    QVERIFY2(written.ok(), qPrintable(written.error().message));
    QCOMPARE(bench.client->readTrack(1, 4)->cams, target.cams);
}

void TestAsciiCamCon::writeTrackLeavesEqualTrackUntouched() {
    Bench bench;
    const Track target = track(5, {{10, 20}, {30, 40}});
    QVERIFY(bench.client->writeTrack(0, target).ok());
    bench.link->resetStats();
    QVERIFY(bench.client->writeTrack(0, target).ok());
    // Only the read: ?NF and one ?NN.
    QCOMPARE(bench.link->stats().requests, 2);
}

void TestAsciiCamCon::outputOneIsProtocolOutputZero() {
    Bench bench;
    QVERIFY(bench.client->writeTrack(7, track(1, {{5, 15}})).ok());
    QCOMPARE(bench.device().state().cams.track(7, 0), (QList<Cam>{{5, 15}}));
    QVERIFY(bench.device().state().cams.track(7, 1).isEmpty());
}

void TestAsciiCamCon::emptyTrackReadsAsNoCams() {
    Bench bench;
    QVERIFY(bench.client->deleteProgram(9).ok());
    const Result<Track> read = bench.client->readTrack(9, 2);
    QVERIFY2(read.ok(), qPrintable(read.error().message));
    QVERIFY(read->cams.isEmpty());
    QCOMPARE(read->output, 2);
}

void TestAsciiCamCon::readProgramListsOnlyTracksWithCams() {
    Bench bench;
    QVERIFY(bench.client->deleteProgram(10).ok());
    QVERIFY(bench.client->writeTrack(10, track(2, {{1, 2}})).ok());
    QVERIFY(bench.client->writeTrack(10, track(32, {{100, 5}})).ok());  // wraps through zero
    QVERIFY(bench.client->writeProgramName(10, QStringLiteral("Label")).ok());
    qint64 lastDone = -1;
    const Result<CamProgram> program =
        bench.client->readProgram(10, 32, [&](qint64 done, qint64) { lastDone = done; });
    QVERIFY2(program.ok(), qPrintable(program.error().message));
    QCOMPARE(program->tracks.keys(), (QList<int>{2, 32}));
    QCOMPARE(program->tracks.value(32).cams, (QList<Cam>{{100, 5}}));
    QCOMPARE(program->name, QStringLiteral("Label"));
    QCOMPARE(lastDone, 32);
}

void TestAsciiCamCon::deadTimesAndNamesRoundTrip() {
    Bench bench;
    QVERIFY(bench.client->writeDeadTime(3, 125).ok());
    QVERIFY(bench.client->writeOutputName(3, QStringLiteral("Glue valve")).ok());
    QVERIFY(bench.client->writeProgramName(4, QStringLiteral("Format B")).ok());
    const Result<DeadTimes> deadTimes = bench.client->readDeadTimes(8);
    QVERIFY2(deadTimes.ok(), qPrintable(deadTimes.error().message));
    QCOMPARE(deadTimes->value(3), 125);
    QCOMPARE(deadTimes->size(), 8);
    QCOMPARE(bench.device().state().deadTimes.value(2), 125);  // 0-based on the device
    QCOMPARE(*bench.client->readOutputName(3), QStringLiteral("Glue valve"));
    QCOMPARE(*bench.client->readProgramName(4), QStringLiteral("Format B"));
}

void TestAsciiCamCon::usersRoundTripAndDelete() {
    Bench bench;
    User user;
    user.name = QStringLiteral("Night shift");
    user.number = QStringLiteral("48151");
    user.outputAccess = QList<bool>(256, false);
    user.outputAccess[0] = true;
    user.outputAccess[9] = true;
    user.rights = User::ProgramSelection | User::Programming;
    QVERIFY(bench.client->writeUser(QString(), user).ok());
    Result<QList<User>> users = bench.client->readUsers();
    QVERIFY2(users.ok(), qPrintable(users.error().message));
    QVERIFY(users->contains(user));
    QVERIFY(bench.client->deleteUser(user.number).ok());
    users = bench.client->readUsers();
    QVERIFY(users.ok());
    QVERIFY(!users->contains(user));
}

void TestAsciiCamCon::plcNetworkRoundTrip() {
    Bench bench;
    PlcNetwork network;
    network.area = PlcNetwork::M;
    network.number = 7;
    network.value = 1500;
    network.reset = 0x0102;
    network.symbols[0] = 0x0105;
    network.symbols[29] = 0x0A03;
    QVERIFY(bench.client->writePlcNetwork(network).ok());
    const Result<PlcNetwork> read = bench.client->readPlcNetwork(PlcNetwork::M, 7);
    QVERIFY2(read.ok(), qPrintable(read.error().message));
    QVERIFY(*read == network);
}

void TestAsciiCamCon::backupRestoreBringsBackTheState() {
    Bench bench;
    QVERIFY(bench.client->writeTrack(1, track(2, {{10, 90}})).ok());
    QVERIFY(bench.client->writeDeadTime(2, 40).ok());
    const Result<EepromImage> image = bench.client->backup();
    QVERIFY2(image.ok(), qPrintable(image.error().message));
    QVERIFY(image->blocks.size() > 1);
    QCOMPARE(image->blocks.first().data.size(), 128);
    const SimState before = bench.device().state();

    QVERIFY(bench.client->writeTrack(1, track(2, {})).ok());
    QVERIFY(bench.client->writeDeadTime(2, 0).ok());
    QVERIFY(!(bench.device().state() == before));

    qint64 lastDone = 0;
    qint64 lastTotal = 0;
    const Status restored = bench.client->restore(*image, [&](qint64 done, qint64 total) {
        lastDone = done;
        lastTotal = total;
    });
    QVERIFY2(restored.ok(), qPrintable(restored.error().message));
    QCOMPARE(lastDone, lastTotal);
    QCOMPARE(bench.client->readTrack(1, 2)->cams, (QList<Cam>{{10, 90}}));
    QCOMPARE(bench.client->readDeadTimes(2)->value(2), 40);
    const Result<EepromImage> again = bench.client->backup();
    QVERIFY(again.ok());
    QCOMPARE(again->blocks, image->blocks);
}

void TestAsciiCamCon::restoreFailureSaysTheDeviceIsErased() {
    Bench bench;
    QVERIFY(bench.client->writeTrack(1, track(2, {{10, 90}})).ok());
    Result<EepromImage> image = bench.client->backup();
    QVERIFY(image.ok());
    QVERIFY(image->blocks.size() > 2);
    // The device rejects a block whose length contradicts its first byte.
    image.value().blocks[1].data.chop(1);
    const Status restored = bench.client->restore(*image);
    QVERIFY(!restored.ok());
    QCOMPARE(restored.error().kind, ErrorKind::DeviceError);
    QVERIFY2(restored.error().message.contains(QLatin1String("ERASED")),
             qPrintable(restored.error().message));
    QVERIFY(restored.error().message.contains(QLatin1String("again is safe")));
}

void TestAsciiCamCon::scanBusFindsExactlyTheDevicesOnTheLine() {
    Bench bench({0, 5}, Framing::Multiuser);
    int calls = 0;
    const Result<QList<int>> found =
        bench.client->scanBus(0, 63, 30, [&](qint64, qint64) { ++calls; });
    QVERIFY2(found.ok(), qPrintable(found.error().message));
    QCOMPARE(*found, (QList<int>{0, 5}));
    QVERIFY(calls >= 64);
}

void TestAsciiCamCon::scanBusRestoresTheLinkSettings() {
    Bench bench({0, 5}, Framing::Multiuser);
    bench.link->setDevice(5);
    const AsciiSettings before = bench.link->settings();
    QVERIFY(bench.client->scanBus(0, 7, 30).ok());
    QCOMPARE(bench.link->settings().device, before.device);
    QCOMPARE(bench.link->settings().timeoutMs, before.timeoutMs);
    QCOMPARE(bench.link->settings().retries, before.retries);
    // And the link still talks to device 5.
    QVERIFY(bench.client->readInfo().ok());
}

void TestAsciiCamCon::everyModelSettingHasACommand() {
    QSet<QString> mapped;
    for (const SettingPage& page : settingPages()) {
        QVERIFY2(findCommand('?', page.command), page.command);
        for (const SettingField& field : page.fields) mapped.insert(QLatin1String(field.key));
    }
    for (const SettingSpec& spec : settingSpecs()) {
        QVERIFY2(mapped.contains(QLatin1String(spec.key)), spec.key);
    }
}

void TestAsciiCamCon::settingsWriteChangesOnlyWhatDiffers() {
    Bench bench;
    QStringList skipped;
    Result<SystemSettings> settings = bench.client->readSettings(&skipped);
    QVERIFY2(settings.ok(), qPrintable(settings.error().message));
    QVERIFY2(skipped.isEmpty(), qPrintable(skipped.join(u';')));
    const qint64 hysteresis = settings->value(QStringLiteral("actualValueHysteresis")).toLongLong();
    settings.value().insert(QStringLiteral("actualValueHysteresis"), hysteresis + 3);
    settings.value().insert(QStringLiteral("speedFormat"), QStringLiteral("###.# U/m"));
    bench.link->resetStats();
    const Status written = bench.client->writeSettings(*settings);
    QVERIFY2(written.ok(), qPrintable(written.error().message));
    // One read of every page, then exactly the two changed commands.
    QCOMPARE(bench.link->stats().requests, int(settingPages().size()) + 2);
    const Result<SystemSettings> again = bench.client->readSettings();
    QVERIFY(again.ok());
    QCOMPARE(again->value(QStringLiteral("actualValueHysteresis")).toLongLong(), hysteresis + 3);
    QCOMPARE(again->value(QStringLiteral("speedFormat")).toString(), QStringLiteral("###.# U/m"));
}

void TestAsciiCamCon::specialEncoderPageWriteSelectsItsType() {
    Bench bench;
    Result<SystemSettings> settings = bench.client->readSettings();
    QVERIFY(settings.ok());
    settings.value().insert(QStringLiteral("specialEncoder.timer.resolution"), 720);
    settings.value().insert(QStringLiteral("specialEncoder.text1"), QStringLiteral("Timer axis"));
    QVERIFY(bench.client->writeSettings(*settings).ok());
    const Result<SystemSettings> again = bench.client->readSettings();
    QVERIFY(again.ok());
    QCOMPARE(again->value(QStringLiteral("specialEncoder.timer.resolution")).toLongLong(), 720);
    QCOMPARE(again->value(QStringLiteral("specialEncoder.type")).toLongLong(), 5);
    QCOMPARE(again->value(QStringLiteral("encoderText1")).toString(), QStringLiteral("Timer axis"));
}

QTEST_GUILESS_MAIN(TestAsciiCamCon)
#include "tst_camcon_client.moc"
