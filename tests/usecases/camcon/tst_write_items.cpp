// The one write path (comm/usecases/write_items.h) against the in-process
// simulator: the check before the first byte, the order of the track
// edits, and the honest report after failures.
#include "sim_bench.h"

#include "comm/camcon/usecases/plan_check.h"
#include "comm/camcon/usecases/read_everything.h"
#include "comm/camcon/usecases/write_items.h"

#include <QLoggingCategory>
#include <QTest>

using namespace cambench;
using namespace cambench::comm;
using namespace cambench::usecases;
using cambench::tests::SimBench;

namespace {

constexpr qint32 kEepromFull = -21;
constexpr qint32 kRefused = -1;

Track track(int output, QList<Cam> cams) {
    Track t;
    t.output = output;
    t.cams = std::move(cams);
    return t;
}

WritePlan trackPlan(int program, const Track& wanted) {
    WritePlan plan;
    plan.tracks << TrackWrite{program, wanted, {}};
    return plan;
}

// Output 1 of program 0 in the demo state: 10..90 and 180..270.
const QList<Cam> kDemoOutput1{{10, 90}, {180, 270}};

}  // namespace

class TestWriteItems : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void overlappingCamsAreRefusedBeforeAnyCommand();
    void fileForBiggerDeviceIsRefusedNamingOutputs();
    void refusedInsertAfterDeleteIsUndoneAndReported();
    void refusedUndoReportsTheTrackAsItIs();
    void refusedFirstInsertLeavesOldCamsUntouched();
    void eepromFullDefersInsertsUntilDeletesMadeRoom();
    void unchangedTrackSendsNothing();
    void emptyTrackOfUnreadProgramIsUnchangedNotWritten();
    void changedTrackReportsWritten();
    void trackChangedOnTheDeviceSinceReadIsNoted();
    void deviceErrorTextSaysWhatOverlapMeans();
    void deadTimesNamesAndPlcAreWrittenOrUnchanged();
    void settingsAreWrittenAgainstTheValuesPassedIn();
    void readOnlySettingThatDiffersIsRefused();
    void communicationSettingsAreLeftOutUnlessAskedByName();
    void communicationSettingsAskedByNameGoLastAndSaySo();
    void unchangedProjectSendsNoCommand();
    void duplicateUserNumberIsRefused();
    void userWithoutNumberKeepsTheDevicesNumber();
    void plcNetworkBeyondTheDevicesCountIsRefused();
    void cancelLeavesTheRestNotSent();
    void deadDeviceStopsTheRunAndSaysSo();
    void summaryCountsAddUp();
};

void TestWriteItems::initTestCase() {
    QLoggingCategory::setFilterRules(
        QStringLiteral("cambench.*.debug=false\ncambench.comm.link.warning=false\n"
                       "cambench.comm.engine.warning=false"));
}

void TestWriteItems::overlappingCamsAreRefusedBeforeAnyCommand() {
    // Issue 6, point 1: 10..90 + 180..270, edited to 10..90 + 80..270.
    SimBench bench;
    const DeviceInfo info = bench.info();
    bench.commandsSent();
    const Result<WriteReport> report =
        writeItems(*bench.client, info, trackPlan(0, track(1, {{10, 90}, {80, 270}})));
    QVERIFY(!report.ok());
    QCOMPARE(report.error().kind, ErrorKind::InvalidData);
    QVERIFY2(report.error().message.contains(QLatin1String("overlaps")),
             qPrintable(report.error().message));
    QVERIFY(report.error().message.contains(QLatin1String("before anything was sent")));
    QCOMPARE(bench.commandsSent(), 0);
    QCOMPARE(bench.device().state().cams.track(0, 0), kDemoOutput1);
}

void TestWriteItems::fileForBiggerDeviceIsRefusedNamingOutputs() {
    SimBench bench;
    const DeviceInfo info = bench.info();
    QCOMPARE(info.outputs, 32);
    WritePlan plan;
    for (int output = 1; output <= 96; ++output)
        plan.tracks << TrackWrite{0, track(output, {{output * 100, output * 100 + 50}}), {}};
    bench.commandsSent();
    const Result<WriteReport> report = writeItems(*bench.client, info, plan);
    QVERIFY(!report.ok());
    QCOMPARE(report.error().kind, ErrorKind::InvalidData);
    const QString message = report.error().message;
    QVERIFY2(message.contains(QLatin1String("outputs 33..96 do not exist on the device (it has "
                                            "1..32)")),
             qPrintable(message));
    QVERIFY(message.contains(QLatin1String("cam points lie outside the device's range 0..359")));
    QVERIFY2(message.contains(QRegularExpression(QStringLiteral("\n  and \\d+ more$"))),
             qPrintable(message));
    QVERIFY(message.count(u'\n') <= 11);  // bounded: summary, ten problems, "and N more"
    QCOMPARE(bench.commandsSent(), 0);
}

void TestWriteItems::refusedInsertAfterDeleteIsUndoneAndReported() {
    // 180..270 becomes 200..300: the new cam overlaps the old one, so the
    // old one must go first. The device refuses the insert (EEPROM full).
    SimBench bench;
    const DeviceInfo info = bench.info();
    bench.injections().refuse(0, '!', "NINS", kEepromFull);
    const Result<WriteReport> report =
        writeItems(*bench.client, info, trackPlan(0, track(1, {{10, 90}, {200, 300}})));
    QVERIFY2(report.ok(), qPrintable(report.error().message));
    const ItemOutcome<Track>& outcome = report->tracks.at(0);
    QCOMPARE(outcome.state, WriteState::Failed);
    QCOMPARE(outcome.error.kind, ErrorKind::DeviceError);
    QVERIFY2(outcome.error.message.contains(QLatin1String("EEPROM is full")),
             qPrintable(outcome.error.message));
    QVERIFY(outcome.error.message.contains(QLatin1String("put back")));
    QCOMPARE(outcome.actual->cams, kDemoOutput1);
    QCOMPARE(outcome.actualText, QStringLiteral("10..90, 180..270"));
    QCOMPARE(bench.device().state().cams.track(0, 0), kDemoOutput1);
    QVERIFY2(
        report->lines().at(0).text.contains(QLatin1String("the device keeps 10..90, 180..270")),
        qPrintable(report->lines().at(0).text));
}

void TestWriteItems::refusedUndoReportsTheTrackAsItIs() {
    // As above, but the device also refuses to take the deleted cam back:
    // the track now holds only 10..90, and the report must say so.
    SimBench bench;
    const DeviceInfo info = bench.info();
    bench.injections().refuse(0, '!', "NINS", kEepromFull);
    bench.injections().refuse(0, '!', "NINS", kEepromFull);
    const Result<WriteReport> report =
        writeItems(*bench.client, info, trackPlan(0, track(1, {{10, 90}, {200, 300}})));
    QVERIFY(report.ok());
    const ItemOutcome<Track>& outcome = report->tracks.at(0);
    QCOMPARE(outcome.state, WriteState::ChangedThoughFailed);
    QCOMPARE(outcome.actual->cams, (QList<Cam>{{10, 90}}));
    QCOMPARE(bench.device().state().cams.track(0, 0), (QList<Cam>{{10, 90}}));
    const QString line = report->lines().at(0).text;
    QVERIFY2(line.contains(QLatin1String("changed though the write failed")), qPrintable(line));
    QVERIFY2(line.contains(QLatin1String("NOW HOLDS 10..90 (before: 10..90, 180..270)")),
             qPrintable(line));
    QVERIFY(!report->complete());
    QCOMPARE(report->count(WriteState::ChangedThoughFailed), 1);
    QVERIFY(report->summary().contains(QLatin1String("1 CHANGED THOUGH THE WRITE FAILED")));
}

void TestWriteItems::refusedFirstInsertLeavesOldCamsUntouched() {
    // A new cam that overlaps nothing goes in before anything is deleted.
    SimBench bench;
    const DeviceInfo info = bench.info();
    bench.injections().refuse(0, '!', "NINS", kRefused);
    bench.commandsSent();
    const Result<WriteReport> report =
        writeItems(*bench.client, info, trackPlan(0, track(1, {{10, 90}, {300, 350}})));
    QVERIFY(report.ok());
    QCOMPARE(report->tracks.at(0).state, WriteState::Failed);
    QCOMPARE(bench.device().state().cams.track(0, 0), kDemoOutput1);
    // One refused insert, no delete: the old cams were never at risk.
    QCOMPARE(bench.injections().count('!', "NDEL"), 0);
    QCOMPARE(bench.injections().count('!', "NINS"), 1);
}

void TestWriteItems::eepromFullDefersInsertsUntilDeletesMadeRoom() {
    SimBench bench;
    const DeviceInfo info = bench.info();
    bench.injections().refuse(0, '!', "NINS", kEepromFull);
    // 180..270 goes, 300..350 comes: the insert first fails for want of
    // room, succeeds after the delete.
    const Result<WriteReport> report =
        writeItems(*bench.client, info, trackPlan(0, track(1, {{10, 90}, {300, 350}})));
    QVERIFY(report.ok());
    QCOMPARE(report->tracks.at(0).state, WriteState::Written);
    QCOMPARE(bench.device().state().cams.track(0, 0), (QList<Cam>{{10, 90}, {300, 350}}));
}

void TestWriteItems::unchangedTrackSendsNothing() {
    SimBench bench;
    const DeviceInfo info = bench.info();
    bench.commandsSent();
    const Result<WriteReport> report =
        writeItems(*bench.client, info, trackPlan(0, track(1, {{180, 270}, {10, 90}})));
    QVERIFY(report.ok());
    QCOMPARE(report->tracks.at(0).state, WriteState::Unchanged);
    QCOMPARE(bench.commandsSent(), 0);
}

void TestWriteItems::emptyTrackOfUnreadProgramIsUnchangedNotWritten() {
    // Issue 6, point 6: a program never read, with no cams, written: nothing
    // is sent, and the report must not say "written".
    SimBench bench;
    const DeviceInfo info = bench.info();
    WritePlan plan;
    for (int output = 1; output <= 4; ++output) plan.tracks << TrackWrite{7, track(output, {}), {}};
    bench.commandsSent();
    const Result<WriteReport> report = writeItems(*bench.client, info, plan);
    QVERIFY(report.ok());
    QCOMPARE(report->count(WriteState::Written), 0);
    QCOMPARE(report->count(WriteState::Unchanged), 4);
    QCOMPARE(bench.commandsSent(), 0);
}

void TestWriteItems::changedTrackReportsWritten() {
    SimBench bench;
    const DeviceInfo info = bench.info();
    const Result<WriteReport> report =
        writeItems(*bench.client, info, trackPlan(3, track(20, {{5, 50}, {300, 2}})));
    QVERIFY(report.ok());
    QCOMPARE(report->tracks.at(0).state, WriteState::Written);
    QCOMPARE(report->tracks.at(0).label, QStringLiteral("program 3, output 20"));
    QCOMPARE(bench.device().state().cams.track(3, 19), (QList<Cam>{{5, 50}, {300, 2}}));
}

void TestWriteItems::trackChangedOnTheDeviceSinceReadIsNoted() {
    SimBench bench;
    const DeviceInfo info = bench.info();
    WritePlan plan;
    plan.tracks << TrackWrite{0, track(1, {{10, 90}, {300, 350}}), track(1, {{10, 90}})};
    const Result<WriteReport> report = writeItems(*bench.client, info, plan);
    QVERIFY(report.ok());
    QCOMPARE(report->tracks.at(0).state, WriteState::Written);
    QCOMPARE(report->lines().at(0).text,
             QStringLiteral("program 0, output 1: written (the device held 10..90, 180..270, not "
                            "10..90 as last read)"));
}

void TestWriteItems::deviceErrorTextSaysWhatOverlapMeans() {
    // The device refuses an insert with -1: the manual gives no meaning, so
    // the report says so and what it means on an insert.
    SimBench bench;
    const DeviceInfo info = bench.info();
    bench.injections().refuse(0, '!', "NINS", kRefused);
    const Result<WriteReport> report =
        writeItems(*bench.client, info, trackPlan(0, track(4, {{100, 120}})));
    QVERIFY(report.ok());
    const QString message = report->tracks.at(0).error.message;
    QVERIFY2(message.contains(QLatin1String("the manual gives no meaning for error -1")) ||
                 message.contains(QLatin1String("The manual gives no meaning for error -1")),
             qPrintable(message));
    QVERIFY(message.contains(QLatin1String("overlaps another cam")));
    QVERIFY(!message.contains(QLatin1String("Unknown error")));
}

void TestWriteItems::deadTimesNamesAndPlcAreWrittenOrUnchanged() {
    SimBench bench;
    const DeviceInfo info = bench.info();
    WritePlan plan;
    plan.deadTimes << DeadTimeWrite{1, 25, {}} << DeadTimeWrite{5, 321, {}};
    plan.outputNames << NameWrite{1, QStringLiteral("Glue valve"), {}}
                     << NameWrite{7, QStringLiteral("Pusher"), {}};
    plan.programNames << NameWrite{3, QStringLiteral("Format C"), QString()};
    PlcNetwork network;
    network.area = PlcNetwork::M;
    network.number = 3;
    network.value = 2500;
    network.symbols[0] = 0x0107;
    plan.plcNetworks << PlcWrite{network, {}};
    const Result<WriteReport> report = writeItems(*bench.client, info, plan);
    QVERIFY2(report.ok(), qPrintable(report.error().message));
    QCOMPARE(report->deadTimes.at(0).state, WriteState::Unchanged);
    QCOMPARE(report->deadTimes.at(1).state, WriteState::Written);
    QCOMPARE(report->outputNames.at(0).state, WriteState::Unchanged);
    QCOMPARE(report->outputNames.at(1).state, WriteState::Written);
    QCOMPARE(report->programNames.at(0).state, WriteState::Written);
    QCOMPARE(report->plcNetworks.at(0).state, WriteState::Written);
    QCOMPARE(bench.device().state().deadTimes.value(4), 321);
    QCOMPARE(bench.device().state().outputNames.value(6), QByteArray("Pusher"));
    QCOMPARE(bench.device().state().programNames.value(3), QByteArray("Format C"));
    QCOMPARE(bench.device().state().plcNetworks.value({0x0A, 3}).value, 2500);
    QVERIFY(report->complete());
}

void TestWriteItems::settingsAreWrittenAgainstTheValuesPassedIn() {
    SimBench bench;
    const DeviceInfo info = bench.info();
    const Result<SystemSettings> onDevice = bench.client->readSettings();
    QVERIFY(onDevice.ok());
    SystemSettings wanted = *onDevice;
    wanted.insert(QStringLiteral("cableLength"),
                  onDevice->value(QStringLiteral("cableLength")).toLongLong() + 17);
    WritePlan plan;
    plan.settings = settingsGroups(wanted);
    plan.settingsOnDevice = *onDevice;
    bench.injections().clearLog();
    const Result<WriteReport> report = writeItems(*bench.client, info, plan);
    QVERIFY2(report.ok(), qPrintable(report.error().message));
    QCOMPARE(report->count(WriteState::Written), 1);
    QCOMPARE(report->count(WriteState::Unchanged), plan.settings.size() - 1);
    // Nothing was read before the write: the caller's values were used.
    for (const SimInjections::Received& received : bench.injections().received())
        QVERIFY2(received.kind == '!', received.name.constData());
    QCOMPARE(bench.injections().commands(), 1);
    const Result<QVariant> cable = bench.client->readSetting(QStringLiteral("cableLength"));
    QCOMPARE(cable->toLongLong(), wanted.value(QStringLiteral("cableLength")).toLongLong());
}

void TestWriteItems::readOnlySettingThatDiffersIsRefused() {
    SimBench bench;
    const DeviceInfo info = bench.info();
    const Result<SystemSettings> onDevice = bench.client->readSettings();
    QVERIFY(onDevice.ok());
    SystemSettings wanted;
    wanted.insert(QStringLiteral("specialEncoder.type"),
                  onDevice->value(QStringLiteral("specialEncoder.type")).toLongLong() + 1);
    WritePlan plan;
    plan.settings = settingsGroups(wanted);
    plan.settingsOnDevice = *onDevice;
    const Result<WriteReport> report = writeItems(*bench.client, info, plan);
    QVERIFY(!report.ok());
    QVERIFY2(report.error().message.contains(QLatin1String("read-only")),
             qPrintable(report.error().message));
}

namespace {

// Another device's settings, as a project of a table-interface CamCon holds
// them (issue 39): its protocol (3964R), its device number, and a cable
// length that differs too.
SystemSettings otherDevicesSettings(const SystemSettings& onDevice) {
    SystemSettings wanted = onDevice;
    wanted.insert(QStringLiteral("protocol"), qint64(4));
    wanted.insert(QStringLiteral("deviceNumber"), qint64(5));
    wanted.insert(QStringLiteral("cableLength"),
                  onDevice.value(QStringLiteral("cableLength")).toLongLong() + 3);
    return wanted;
}

QStringList commandNames(const SimInjections& injections) {
    QStringList names;
    for (const SimInjections::Received& received : injections.received())
        if (received.kind == '!') names << QString::fromLatin1(received.name);
    return names;
}

}  // namespace

// Issue 39: a project written to a Standard device changed its protocol to
// the project's (3964R); the next connection failed.
void TestWriteItems::communicationSettingsAreLeftOutUnlessAskedByName() {
    SimBench bench;
    const DeviceInfo info = bench.info();
    const Result<SystemSettings> onDevice = bench.client->readSettings();
    QVERIFY(onDevice.ok());
    QCOMPARE(onDevice->value(QStringLiteral("protocol")).toLongLong(), 1);  // Standard
    WritePlan plan;
    plan.settings = settingsGroups(otherDevicesSettings(*onDevice));
    plan.settingsOnDevice = *onDevice;
    bench.injections().clearLog();
    const Result<WriteReport> report = writeItems(*bench.client, info, plan);
    QVERIFY2(report.ok(), qPrintable(report.error().message));
    QVERIFY(report->complete());
    // The cable length went; neither !GSIO nor !GNR did.
    QCOMPARE(commandNames(bench.injections()), QStringList{QStringLiteral("GKL")});
    QCOMPARE(report->count(WriteState::Written), 1);
    QVERIFY(report->linkSettings.isEmpty());
    QCOMPARE(report->linkSettingsLeftOut.keys(),
             QStringList({QStringLiteral("deviceNumber"), QStringLiteral("protocol")}));
    for (const OutcomeLine& line : report->lines())
        QVERIFY2(!line.label.contains(QLatin1String("protocol")), qPrintable(line.text));
    QVERIFY2(report->summary().contains(QLatin1String(
                 "Communication settings left out: Device number 5, Communication protocol "
                 "3964R (the device keeps Device number 0, Communication protocol Standard)")),
             qPrintable(report->summary()));
    QCOMPARE(bench.client->readSetting(QStringLiteral("protocol"))->toLongLong(), 1);
    QCOMPARE(bench.client->readSetting(QStringLiteral("deviceNumber"))->toLongLong(), 0);
}

void TestWriteItems::communicationSettingsAskedByNameGoLastAndSaySo() {
    SimBench bench;
    const DeviceInfo info = bench.info();
    const Result<SystemSettings> onDevice = bench.client->readSettings();
    QVERIFY(onDevice.ok());
    WritePlan plan;
    plan.settings = settingsGroups(otherDevicesSettings(*onDevice));
    plan.settingsOnDevice = *onDevice;
    plan.linkSettingsAsked = {QStringLiteral("protocol")};
    plan.programNames << NameWrite{1, QStringLiteral("Night"), {}};
    bench.injections().clearLog();
    const Result<WriteReport> report = writeItems(*bench.client, info, plan);
    QVERIFY2(report.ok(), qPrintable(report.error().message));
    // The protocol last of all, after the program name; the device number
    // was not asked for.
    const QStringList sent = commandNames(bench.injections());
    QCOMPARE(sent.last(), QStringLiteral("GSIO"));
    QCOMPARE(sent.count(QStringLiteral("GSIO")), 1);
    QVERIFY(!sent.contains(QStringLiteral("GNR")));
    QCOMPARE(report->linkSettings.size(), 1);
    QCOMPARE(report->linkSettings.first().state, WriteState::Written);
    QCOMPARE(report->lines().last().label, QStringLiteral("settings configuration (protocol)"));
    QCOMPARE(report->linkSettingsLeftOut.keys(), QStringList{QStringLiteral("deviceNumber")});
    QVERIFY2(report->summary().contains(QLatin1String(
                 "Communication settings written: the next connection to this device needs "
                 "Communication protocol 3964R.")),
             qPrintable(report->summary()));
    // (The simulator goes on speaking Standard; a real device would not.)
    QCOMPARE(bench.client->readSetting(QStringLiteral("protocol"))->toLongLong(), 4);
}

// Issue 39: the device's own project written back changes nothing and
// sends no command at all.
void TestWriteItems::unchangedProjectSendsNoCommand() {
    SimBench bench;
    const DeviceInfo info = bench.info();
    const Result<ReadEverything> read = readEverything(*bench.client, info);
    QVERIFY2(read.ok(), qPrintable(read.error().message));
    bench.injections().clearLog();
    const Result<WriteReport> report =
        writeItems(*bench.client, info, planFromProject(read->project, read->project));
    QVERIFY2(report.ok(), qPrintable(report.error().message));
    QVERIFY(report->total() > 20);
    QStringList changed;
    for (const OutcomeLine& line : report->lines())
        if (line.state != WriteState::Unchanged) changed << line.text;
    QVERIFY2(changed.isEmpty(), qPrintable(changed.join(QLatin1Char('\n'))));
    QCOMPARE(commandNames(bench.injections()), QStringList());
    QVERIFY(report->notes.isEmpty());
}

void TestWriteItems::duplicateUserNumberIsRefused() {
    SimBench bench;
    const DeviceInfo info = bench.info();
    User user;
    user.name = QStringLiteral("Night shift");
    user.number = QStringLiteral("4711");  // the Supervisor's
    WritePlan plan;
    plan.users << UserWrite{{}, user};
    bench.commandsSent();
    const Result<WriteReport> report = writeItems(*bench.client, info, plan);
    QVERIFY(!report.ok());
    QVERIFY2(report.error().message.contains(QLatin1String("same user number")),
             qPrintable(report.error().message));
    QVERIFY(!report.error().message.contains(QLatin1String("4711")));  // an access code
    QCOMPARE(bench.commandsSent(), 0);
}

void TestWriteItems::userWithoutNumberKeepsTheDevicesNumber() {
    // A project saved without user numbers: the operator gets new rights,
    // and keeps the number the device has for it.
    SimBench bench;
    const DeviceInfo info = bench.info();
    const QList<User> users = *bench.client->readUsers();
    User changed = users.at(1);
    QCOMPARE(changed.name, QStringLiteral("Operator"));
    changed.number.clear();
    changed.rights = 0x03;
    WritePlan plan;
    plan.users << UserWrite{{}, changed};
    const Result<WriteReport> report = writeItems(*bench.client, info, plan);
    QVERIFY2(report.ok(), qPrintable(report.error().message));
    QCOMPARE(report->users.at(0).state, WriteState::Written);
    const QList<User> after = *bench.client->readUsers();
    QCOMPARE(after.size(), 2);
    QCOMPARE(after.at(1).number, QStringLiteral("1234"));
    QCOMPARE(after.at(1).rights, 0x03u);
}

void TestWriteItems::plcNetworkBeyondTheDevicesCountIsRefused() {
    SimBench bench;
    const DeviceInfo info = bench.info();
    PlcNetwork network;
    network.area = PlcNetwork::M;
    network.number = 40;  // the demo device has 32 flags
    WritePlan plan;
    plan.plcNetworks << PlcWrite{network, {}};
    const Result<WriteReport> report = writeItems(*bench.client, info, plan);
    QVERIFY(!report.ok());
    QVERIFY2(report.error().message.contains(QLatin1String("PLC network M40")),
             qPrintable(report.error().message));
}

void TestWriteItems::cancelLeavesTheRestNotSent() {
    SimBench bench;
    const DeviceInfo info = bench.info();
    WritePlan plan;
    for (int output = 1; output <= 3; ++output)
        plan.deadTimes << DeadTimeWrite{output, 100 + output, 0};
    int asked = 0;
    const UseCaseProgress progress({}, [&asked] { return ++asked > 2; });
    const Result<WriteReport> report = writeItems(*bench.client, info, plan, progress);
    QVERIFY(report.ok());
    QCOMPARE(report->deadTimes.at(0).state, WriteState::Written);
    QCOMPARE(report->deadTimes.at(1).state, WriteState::NotSent);
    QCOMPARE(report->deadTimes.at(2).state, WriteState::NotSent);
    QCOMPARE(report->deadTimes.at(2).error.kind, ErrorKind::Cancelled);
    QCOMPARE(bench.device().state().deadTimes.value(1), 120);  // output 2 untouched
}

void TestWriteItems::deadDeviceStopsTheRunAndSaysSo() {
    SimBench bench;
    const DeviceInfo info = bench.info();
    WritePlan plan;
    plan.outputNames << NameWrite{8, QStringLiteral("A"), QString()}
                     << NameWrite{9, QStringLiteral("B"), QString()}
                     << NameWrite{10, QStringLiteral("C"), QString()};
    bench.injections().setDead(0, true);
    const Result<WriteReport> report = writeItems(*bench.client, info, plan);
    QVERIFY(report.ok());
    QCOMPARE(report->outputNames.at(0).state, WriteState::Unknown);
    QCOMPARE(report->outputNames.at(1).state, WriteState::NotSent);
    QVERIFY2(report->outputNames.at(1).error.message.contains(QLatin1String("name of output 8")),
             qPrintable(report->outputNames.at(1).error.message));
    QCOMPARE(report->firstError().kind, ErrorKind::Communication);
}

void TestWriteItems::summaryCountsAddUp() {
    SimBench bench;
    const DeviceInfo info = bench.info();
    WritePlan plan;
    for (int output = 1; output <= 32; ++output)
        plan.deadTimes << DeadTimeWrite{output, output == 3 ? 77 : 0, std::nullopt};
    const Result<WriteReport> report = writeItems(*bench.client, info, plan);
    QVERIFY(report.ok());
    // The demo device: 2.5 ms on 1, 12.0 ms on 2, 999.9 ms on 4.
    QCOMPARE(report->total(), 32);
    QCOMPARE(report->count(WriteState::Written), 4);
    QCOMPARE(report->count(WriteState::Unchanged), 28);
    QCOMPARE(report->summary(), QStringLiteral("32 items: 4 written, 28 unchanged"));
}

QTEST_GUILESS_MAIN(TestWriteItems)
#include "tst_write_items.moc"
