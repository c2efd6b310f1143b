// Reading a whole device into a project, saving and loading it, and writing
// a project back through the one write path.
#include "sim_bench.h"

#include "comm/camcon/usecases/read_everything.h"
#include "comm/camcon/usecases/write_items.h"
#include "model/camcon/project_file.h"

#include <QLoggingCategory>
#include <QTemporaryDir>
#include <QTest>

using namespace cambench;
using namespace cambench::comm;
using namespace cambench::usecases;
using cambench::tests::SimBench;

class TestReadEverything : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void readsEveryPartWithItsTime();
    void progressRunsOnOneBarToTheEnd();
    void devicesOwnValuesSaveAndLoad();
    void projectWrittenBackIsUnchangedEverywhere();
    void editedProjectWritesOnlyWhatDiffers();
    void projectForBiggerDeviceIsRefusedBeforeAnyCommand();
    void cancelStopsTheRead();
};

void TestReadEverything::initTestCase() {
    QLoggingCategory::setFilterRules(QStringLiteral("cambench.*.debug=false"));
}

void TestReadEverything::readsEveryPartWithItsTime() {
    SimBench bench;
    const DeviceInfo info = bench.info();
    const QDateTime before = QDateTime::currentDateTimeUtc().addSecs(-1);
    const Result<ReadEverything> read = readEverything(*bench.client, info);
    QVERIFY2(read.ok(), qPrintable(read.error().message));
    const Project& project = read->project;
    QCOMPARE(project.device, info);
    // Every program, also the empty ones: "not read" is not "empty".
    QCOMPARE(project.programs.size(), info.programs);
    QCOMPARE(project.readAt.programs.size(), info.programs);
    QCOMPARE(project.programs.at(0).name, QStringLiteral("Standard"));
    QCOMPARE(project.programs.at(2).tracks.value(6).cams, (QList<Cam>{{5, 355}}));
    QVERIFY(project.programs.at(9).tracks.isEmpty());
    for (ProjectPart part :
         {ProjectPart::Device, ProjectPart::Settings, ProjectPart::DeadTimes,
          ProjectPart::OutputNames, ProjectPart::Users, ProjectPart::PlcNetworks}) {
        QVERIFY(project.readAt.parts.contains(part));
        QVERIFY(project.readAt.parts.value(part) >= before);
    }
    QCOMPARE(project.deadTimes.value(4), 9999);
    QCOMPARE(project.names.outputs.value(2), QStringLiteral("Knife"));
    QCOMPARE(project.users.size(), 2);
    QCOMPARE(project.plcNetworks.size(), 2);
    QVERIFY(read->skipped.isEmpty());
}

void TestReadEverything::progressRunsOnOneBarToTheEnd() {
    SimBench bench;
    const DeviceInfo info = bench.info();
    qint64 last = -1;
    qint64 total = 0;
    bool backwards = false;
    const UseCaseProgress progress([&](qint64 done, qint64 all, const QString&) {
        if (all == total && done < last) backwards = true;
        last = done;
        total = all;
    });
    QVERIFY(readEverything(*bench.client, info, progress).ok());
    QVERIFY(!backwards);
    QVERIFY(total > info.programs * info.outputs);
    QCOMPARE(last, total);
}

void TestReadEverything::devicesOwnValuesSaveAndLoad() {
    // The demo device holds specialEncoder.incremental.divider 0, below the
    // manual's minimum: a warning, never a refusal (issue 6, point 6).
    SimBench bench;
    const Result<ReadEverything> read = readEverything(*bench.client, bench.info());
    QVERIFY(read.ok());
    QCOMPARE(read->project.settings.value(QStringLiteral("specialEncoder.incremental.divider"))
                 .toLongLong(),
             0);
    QVERIFY(!validateProject(read->project).isEmpty());
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("device.cambench"));
    const Status saved = saveProject(path, read->project, {true});
    QVERIFY2(saved.ok(), qPrintable(saved.error().message));
    const Result<Project> loaded = loadProject(path);
    QVERIFY2(loaded.ok(), qPrintable(loaded.error().message));
    QCOMPARE(loaded->settings, read->project.settings);
    QCOMPARE(loaded->programs, read->project.programs);
    QCOMPARE(loaded->users, read->project.users);
    QCOMPARE(loaded->readAt.programs.keys(), read->project.readAt.programs.keys());
}

void TestReadEverything::projectWrittenBackIsUnchangedEverywhere() {
    SimBench bench;
    const DeviceInfo info = bench.info();
    const Result<ReadEverything> read = readEverything(*bench.client, info);
    QVERIFY(read.ok());
    const WritePlan plan = planFromProject(read->project, read->project);
    bench.commandsSent();
    const Result<WriteReport> report = writeItems(*bench.client, info, plan);
    QVERIFY2(report.ok(), qPrintable(report.error().message));
    QCOMPARE(report->count(WriteState::Written), 0);
    QCOMPARE(report->count(WriteState::Unchanged), report->total());
    QCOMPARE(bench.commandsSent(), 0);
}

void TestReadEverything::editedProjectWritesOnlyWhatDiffers() {
    SimBench bench;
    const DeviceInfo info = bench.info();
    const Result<ReadEverything> read = readEverything(*bench.client, info);
    QVERIFY(read.ok());
    Project edited = read->project;
    edited.programs[1].tracks[4] = Track{4, {{10, 20}}};
    edited.programs[1].tracks.remove(1);  // 45..200 on output 1 goes
    edited.deadTimes.insert(2, 130);
    // Saved without user numbers: they stay as on the device.
    for (User& user : edited.users) user.number.clear();
    const WritePlan plan = planFromProject(edited, read->project);
    const Result<WriteReport> report = writeItems(*bench.client, info, plan);
    QVERIFY2(report.ok(), qPrintable(report.error().message));
    QCOMPARE(report->count(WriteState::Written), 3);
    QVERIFY(report->complete());
    QCOMPARE(bench.device().state().cams.track(1, 3), (QList<Cam>{{10, 20}}));
    QVERIFY(bench.device().state().cams.track(1, 0).isEmpty());
    QCOMPARE(bench.device().state().users.at(0).number, QByteArray("4711"));
}

void TestReadEverything::projectForBiggerDeviceIsRefusedBeforeAnyCommand() {
    // Issue 6, point 3: a 96-output project (0..12499) to a 32-output device.
    SimBench bench;
    const DeviceInfo info = bench.info();
    Project big;
    big.device = info;
    big.device.outputs = 96;
    big.device.maxPosition = 12499;
    CamProgram program;
    for (int output = 1; output <= 96; ++output)
        program.tracks.insert(output, Track{output, {{output * 100, output * 100 + 90}}});
    big.programs << program;
    Project onDevice;
    onDevice.device = info;
    onDevice.readAt.parts.insert(ProjectPart::Device, QDateTime::currentDateTimeUtc());
    bench.commandsSent();
    const Result<WriteReport> report =
        writeItems(*bench.client, info, planFromProject(big, onDevice));
    QVERIFY(!report.ok());
    QVERIFY2(report.error().message.contains(QLatin1String("outputs 33..96")),
             qPrintable(report.error().message));
    QCOMPARE(bench.commandsSent(), 0);
    QCOMPARE(bench.device().state().cams.track(0, 0), (QList<Cam>{{10, 90}, {180, 270}}));
}

void TestReadEverything::cancelStopsTheRead() {
    SimBench bench;
    int asked = 0;
    const Result<ReadEverything> read = readEverything(
        *bench.client, bench.info(), UseCaseProgress({}, [&asked] { return ++asked > 3; }));
    QVERIFY(!read.ok());
    QCOMPARE(read.error().kind, ErrorKind::Cancelled);
}

QTEST_GUILESS_MAIN(TestReadEverything)
#include "tst_read_everything.moc"
