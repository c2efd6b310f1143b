// Reading program N (usecases::readProgram): the one range check and its
// text, what is sent for a program, and that nothing is sent for a program
// the device does not have; on two devices that differ in their outputs.
#include "sim_bench.h"

#include "comm/camcon/usecases/program_read.h"

#include <QLoggingCategory>
#include <QTest>

using namespace cambench;
using namespace cambench::comm;
using namespace cambench::usecases;
using cambench::tests::SimBench;

namespace {

// The demo device and one with 8 outputs and another firmware date.
std::unique_ptr<SimBench> bench(bool other) {
    if (!other) return std::make_unique<SimBench>();
    SimPortConfig config;
    config.outputs = 8;
    config.epromDate = "01.02.2003";
    return std::make_unique<SimBench>(config);
}

}  // namespace

class TestProgramRead : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void readsEveryOutputAndTheNameOnce_data();
    void readsEveryOutputAndTheNameOnce();
    void programOutsideTheDeviceSendsNothing_data();
    void programOutsideTheDeviceSendsNothing();
    void refusalNamesTheDevicesPrograms();
    void identityIsReadFirstWhenNotHeld();
    void cancelledBeforeStartSendsNothing();
};

void TestProgramRead::initTestCase() {
    QLoggingCategory::setFilterRules(QStringLiteral("cambench.*.debug=false"));
}

void TestProgramRead::readsEveryOutputAndTheNameOnce_data() {
    QTest::addColumn<bool>("other");
    QTest::newRow("demo device") << false;
    QTest::newRow("8 outputs") << true;
}

void TestProgramRead::readsEveryOutputAndTheNameOnce() {
    QFETCH(bool, other);
    const auto b = bench(other);
    const DeviceInfo info = b->info();
    QCOMPARE(info.outputs == 8, other);
    b->injections().clearLog();
    const Result<CamProgram> read = readProgram(*b->client, info, 2);
    QVERIFY2(read.ok(), qPrintable(read.error().message));
    QCOMPARE(read->number, 2);
    QCOMPARE(read->tracks.value(6).cams, (QList<Cam>{{5, 355}}));
    // One ?NF per output of this device, the name once (the device's
    // readProgram reads it; nobody asks a second time), nothing written.
    QCOMPARE(b->injections().count('?', "NF"), info.outputs);
    QCOMPARE(b->injections().count('?', "PNAME"), 1);
    QCOMPARE(b->injections().commands(), 0);
    QVERIFY(b->injections().count('?', "EPROM") == 0);
}

void TestProgramRead::programOutsideTheDeviceSendsNothing_data() {
    QTest::addColumn<int>("program");
    QTest::newRow("one past the last") << 16;
    QTest::newRow("far beyond") << 999;
    QTest::newRow("negative") << -1;
}

void TestProgramRead::programOutsideTheDeviceSendsNothing() {
    QFETCH(int, program);
    SimBench b;
    const DeviceInfo info = b.info();
    QCOMPARE(info.programs, 16);
    b.injections().clearLog();
    const Result<CamProgram> read = readProgram(*b.client, info, program);
    QVERIFY(!read.ok());
    QCOMPARE(read.error().kind, ErrorKind::InvalidData);
    QVERIFY(b.injections().received().isEmpty());
}

void TestProgramRead::refusalNamesTheDevicesPrograms() {
    // What, which range, what to do - the same words for GUI and CLI.
    DeviceInfo small;
    small.programs = 4;
    DeviceInfo large;
    large.programs = 100;
    QCOMPARE(checkProgramNumber(4, small).error().message,
             QStringLiteral("program 4 does not exist on the device (it has programs 0 to 3): "
                            "choose one of those"));
    QCOMPARE(checkProgramNumber(100, large).error().message,
             QStringLiteral("program 100 does not exist on the device (it has programs 0 to "
                            "99): choose one of those"));
    QVERIFY(checkProgramNumber(4, large).ok());
    QVERIFY(checkProgramNumber(0, small).ok());
    QVERIFY(checkProgramNumber(3, small).ok());
}

void TestProgramRead::identityIsReadFirstWhenNotHeld() {
    for (bool other : {false, true}) {
        const auto b = bench(other);
        const DeviceInfo info = b->info();
        b->injections().clearLog();
        const Result<ProgramRead> read = readIdentityAndProgram(*b->client, 0);
        QVERIFY2(read.ok(), qPrintable(read.error().message));
        QCOMPARE(read->device, info);
        QCOMPARE(read->program.name, QStringLiteral("Standard"));
        QCOMPARE(b->injections().count('?', "EPROM"), 1);
        QCOMPARE(b->injections().count('?', "NF"), info.outputs);
        // Refused after the identity: no cams asked for.
        b->injections().clearLog();
        const Result<ProgramRead> beyond = readIdentityAndProgram(*b->client, info.programs);
        QVERIFY(!beyond.ok());
        QVERIFY(beyond.error().message.contains(QStringLiteral("programs 0 to 15")));
        QCOMPARE(b->injections().count('?', "EPROM"), 1);
        QCOMPARE(b->injections().count('?', "NF"), 0);
        QCOMPARE(b->injections().count('?', "PNAME"), 0);
    }
}

void TestProgramRead::cancelledBeforeStartSendsNothing() {
    SimBench b;
    const DeviceInfo info = b.info();
    b.injections().clearLog();
    const UseCaseProgress cancelled([](qint64, qint64, const QString&) {}, [] { return true; });
    const Result<CamProgram> read = readProgram(*b.client, info, 0, cancelled);
    QVERIFY(!read.ok());
    QCOMPARE(read.error().kind, ErrorKind::Cancelled);
    QVERIFY(b.injections().received().isEmpty());
}

QTEST_GUILESS_MAIN(TestProgramRead)
#include "tst_program_read.moc"
