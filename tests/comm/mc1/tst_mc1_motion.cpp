// Issue 27 for the MC-1: STOP of every axis the controller has (stops back
// to back, read-backs after, a lost answer sent again), the axes found with
// RDTABLE, an acknowledged command that stays done when its read-back is
// refused, the axis parameter numbers as data (the provisional guess said
// as such, the controller's own table loaded or refused), and the acting
// telegrams' bytes pinned to the manual (tables 41-45), written here by
// hand: opcode, checksum (the sum of every byte but the second), data.
#include "mc1_test_bench.h"

#include "comm/mc1/mc1_parameters.h"

#include <QTest>

using namespace cambench;
using namespace cambench::comm;

namespace {

using Bench = Mc1TestBench;

QByteArray hex(const char* text) {
    return QByteArray::fromHex(QByteArray(text).replace(' ', ""));
}

// The telegrams of one opcode the simulated controller received.
QList<QByteArray> receivedOf(Bench& bench, quint8 opcode) {
    QList<QByteArray> found;
    for (const QByteArray& telegram : bench.sim().received())
        if (quint8(telegram.at(0)) == opcode) found << telegram;
    return found;
}

Mc1SimAxes withAxes(const QList<int>& axes, std::optional<quint16> parameterBase = std::nullopt) {
    Mc1SimAxes simulated;
    simulated.axes = axes;
    simulated.parameterBase = parameterBase;
    return simulated;
}

// The stop telegram (AXIS_NODATA 9B, command 09: stop with the maximum
// ramp) for axes 1..8, by hand: 9B + axis + 09 is the checksum.
const char* const kStops[] = {"9B A5 01 09", "9B A6 02 09", "9B A7 03 09", "9B A8 04 09",
                              "9B A9 05 09", "9B AA 06 09", "9B AB 07 09", "9B AC 08 09"};

}  // namespace

class TestMc1Motion : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void actingTelegramsAreTheManualsBytes() {
        Bench bench(Mc1Variant::Mc200V2);
        Mc1Device& device = bench.device;
        QVERIFY(device.axes().ok());
        QVERIFY(device.axisCommand(2, Mc1AxisCommand::MoveAbsolute, 1000).ok());
        QVERIFY(device.axisCommand(1, Mc1AxisCommand::MoveRelative, 100).ok());
        QVERIFY(device.axisCommand(3, Mc1AxisCommand::JogPlus).ok());
        QVERIFY(device.axisCommand(3, Mc1AxisCommand::JogMinus).ok());
        QVERIFY(device.axisCommand(1, Mc1AxisCommand::Home).ok());
        QVERIFY(device.axisCommand(1, Mc1AxisCommand::Stop).ok());
        QVERIFY(device.axisCommand(5, Mc1AxisCommand::QuickStop).ok());
        // Table 44/45: 9F, checksum, axis, command, i32 little-endian.
        QCOMPARE(receivedOf(bench, 0x9F),
                 QList<QByteArray>({hex("9F 8F 02 03 E8 03 00 00"),     // to 1000 (03)
                                    hex("9F 08 01 04 64 00 00 00"),     // by 100 (04)
                                    hex("9F A8 03 05 01 00 00 00"),     // continuous + (05, 1)
                                    hex("9F A7 03 05 00 00 00 00")}));  // continuous - (05, 0)
        // Table 41/42: 9B, checksum, axis, command.
        QCOMPARE(receivedOf(bench, 0x9B),
                 QList<QByteArray>({hex("9B A2 01 06"),  // home (the notes' own vector)
                                    hex("9B A4 01 08"),  // stop, programmed ramp
                                    hex(kStops[4])}));   // stop, maximum ramp
        // Table 26: RDTABLE E5, checksum, 00, 00, logical axis, 00 - axis 1..8.
        const QList<QByteArray> table = receivedOf(bench, 0xE5);
        QCOMPARE(table.size(), 8);
        QCOMPARE(table.at(2), hex("E5 E8 00 00 03 00"));
    }

    void stopOfAllSendsEveryStopBeforeAnyReadBack() {
        Bench bench(Mc1Variant::Mc200V2);
        for (int axis = 1; axis <= 8; ++axis)
            QVERIFY(bench.device.axisCommand(axis, Mc1AxisCommand::JogPlus).ok());
        const qsizetype before = bench.sim().received().size();
        MotionControl* motion = bench.device.motionControl();
        QVERIFY(motion);
        const MotionStopReport report = motion->stopAllMotion();
        QVERIFY(report.allAcknowledged());
        QCOMPARE(report.lines.size(), 8);
        const QList<QByteArray> sent = bench.sim().received().mid(before);
        for (int i = 0; i < 8; ++i) QCOMPARE(sent.at(i), hex(kStops[i]));
        // Then only reads: three RDSTAT per axis.
        QCOMPARE(sent.size(), 8 + 8 * 3);
        for (qsizetype i = 8; i < sent.size(); ++i)
            QCOMPARE(quint8(sent.at(i).at(0)), quint8(0xE3));
        for (const MotionStopLine& line : report.lines)
            QVERIFY2(line.detail.contains(QLatin1String("stands at")), qPrintable(line.detail));
        // "Not moving" read through the guessed parameter numbers is no
        // fact (issue 35): "could not tell", never "nothing moves".
        const Result<QStringList> moving = motion->activeMotion();
        QVERIFY(!moving.ok());
        QVERIFY2(moving.error().message.startsWith(
                     QLatin1String("could not tell whether axis 1, 2, 3, 4, 5, 6, 7, 8 moves")),
                 qPrintable(moving.error().message));
        // Read through the controller's own numbers, standing still is a fact.
        bench.device.setAxisParameters(mc1AxisParametersFrom(0x1000, QStringLiteral("its own")));
        QVERIFY(motion->activeMotion()->isEmpty());
    }

    void aControllerWithFewerAxesGetsStopsOnlyForItsAxes() {
        // Two controllers that differ: axes 1, 2 and 5, and all eight.
        Bench three(Mc1Variant::Mc200V2, std::nullopt, {}, 0, withAxes({1, 2, 5}));
        Bench eight(Mc1Variant::Mc200V2);
        const Result<Mc1Axes> found = three.device.axes();
        QCOMPARE(found->numbers, QList<int>({1, 2, 5}));
        QVERIFY2(found->source.contains(QLatin1String("RDTABLE")), qPrintable(found->source));
        QVERIFY(three.device.axisCommand(5, Mc1AxisCommand::JogMinus).ok());
        const Result<QStringList> moving = three.device.motionControl()->activeMotion();
        QVERIFY2(moving.error().message.contains(
                     QLatin1String("could not tell whether axis 1, 2 moves")) &&
                     moving.error().message.contains(
                         QLatin1String("(besides: axis 5 moves (provisional parameter numbers))")),
                 qPrintable(moving.error().message));
        const MotionStopReport report = three.device.motionControl()->stopAllMotion();
        QVERIFY(report.allAcknowledged());  // no false alarm for the axes it lacks
        QCOMPARE(report.lines.size(), 3);
        QCOMPARE(report.lines.at(2).what, QStringLiteral("Axis 5"));
        QCOMPARE(receivedOf(three, 0x9B),
                 QList<QByteArray>({hex(kStops[0]), hex(kStops[1]), hex(kStops[4])}));
        QCOMPARE(eight.device.motionControl()->stopAllMotion().lines.size(), 8);
        QCOMPARE(receivedOf(eight, 0x9B).size(), 8);
        // A single command for an axis it lacks is refused before a byte.
        const Result<Mc1AxisDone> refused =
            three.device.axisCommand(4, Mc1AxisCommand::MoveRelative, 10);
        QCOMPARE(refused.error().kind, ErrorKind::Usage);
        QVERIFY2(refused.error().message.contains(QLatin1String("1, 2, 5")),
                 qPrintable(refused.error().message));
        QCOMPARE(receivedOf(three, 0x9F).size(), 1);
        // Nor is it read: no RDSTAT for axis 4.
        const qsizetype reads = receivedOf(three, 0xE3).size();
        QCOMPARE(three.device.axisState(4).error().kind, ErrorKind::Usage);
        QCOMPARE(receivedOf(three, 0xE3).size(), reads);
    }

    // Issue 35, item 6: the STOP sends its stops before anything else. With
    // the axes not known and the controller not identified, every axis an
    // MC-1 can have gets its stop - no probe, no RDTABLE before them - and
    // an axis the controller lacks says "no such axis", not an alarm.
    void aStopWithNothingKnownSendsEveryStopFirst() {
        Bench three(Mc1Variant::Mc200V2, std::nullopt, {}, 0, withAxes({1, 2, 5}));
        MotionControl* motion = three.device.motionControl();
        QVERIFY(motion);
        QVERIFY(three.sim().received().isEmpty());  // asking for it sent nothing
        const MotionStopReport report = motion->stopAllMotion();
        const QList<QByteArray> sent = three.sim().received();
        QVERIFY(sent.size() >= 8);
        for (int i = 0; i < 8; ++i) QCOMPARE(sent.at(i), hex(kStops[i]));
        QVERIFY(receivedOf(three, 0xE5).isEmpty());  // no RDTABLE at all
        QCOMPARE(report.lines.size(), 8);
        QVERIFY2(report.allAcknowledged(), "no alarm for axes it lacks");
        for (int axis = 1; axis <= 8; ++axis) {
            const MotionStopLine& line = report.lines.at(axis - 1);
            const bool has = axis == 1 || axis == 2 || axis == 5;
            QCOMPARE(line.acknowledged, has);
            QCOMPARE(line.absent, !has);
            if (!has)
                QVERIFY2(line.detail.startsWith(QLatin1String("no such axis")),
                         qPrintable(line.detail));
            else
                QVERIFY2(line.detail.contains(QLatin1String("stands at")), qPrintable(line.detail));
        }
        // Identified, axes still unknown: the same eight, still no RDTABLE first.
        Bench eight(Mc1Variant::Mc200V2);
        QVERIFY(eight.device.ensureIdentified().ok());
        const qsizetype before = eight.sim().received().size();
        QVERIFY(eight.device.motionControl()->stopAllMotion().allAcknowledged());
        const QList<QByteArray> after = eight.sim().received().mid(before);
        for (int i = 0; i < 8; ++i) QCOMPARE(after.at(i), hex(kStops[i]));
        QVERIFY(receivedOf(eight, 0xE5).isEmpty());
    }

    void anAxisTheControllerIsKnownToHaveThatRefusesIsAnAlarm() {
        // A refusal from an axis RDTABLE found is no "no such axis".
        Bench bench(Mc1Variant::Mc200V2, std::nullopt, {}, 0, withAxes({1, 2}));
        QVERIFY(bench.device.axes().ok());
        bench.device.setGivenAxes(QList<int>{1, 2, 3});  // told wrong: axis 3 refuses
        const MotionStopReport report = bench.device.motionControl()->stopAllMotion();
        QVERIFY(!report.allAcknowledged());
        QVERIFY(!report.lines.at(2).absent);
        QVERIFY2(report.lines.at(2).detail.startsWith(QLatin1String("not acknowledged")),
                 qPrintable(report.lines.at(2).detail));
    }

    void givenAxesReplaceTheSearch() {
        Bench bench(Mc1Variant::Mc200V2, std::nullopt, {}, 0, withAxes({1, 2, 5}));
        bench.device.setGivenAxes(QList<int>{1, 2});
        const MotionStopReport report = bench.device.motionControl()->stopAllMotion();
        QVERIFY(report.allAcknowledged());
        QCOMPARE(report.lines.size(), 2);
        QVERIFY(receivedOf(bench, 0xE5).isEmpty());
    }

    void aLostStopAnswerIsSentAgainAfterTheOthers() {
        SimFaultSettings faults;
        faults.dropFirstReplyTo = QByteArray(1, char(0x9B));  // the first stop's ACK
        Bench bench(Mc1Variant::Mc200V2, std::nullopt, faults, 0, withAxes({1, 2, 3}));
        QVERIFY(bench.device.axes().ok());
        const MotionStopReport report = bench.device.motionControl()->stopAllMotion();
        QVERIFY(report.allAcknowledged());
        QCOMPARE(receivedOf(bench, 0x9B), QList<QByteArray>({hex(kStops[0]), hex(kStops[1]),
                                                             hex(kStops[2]), hex(kStops[0])}));
    }

    void anAcknowledgedCommandWhoseReadBacksAreRefusedIsDone() {
        // Its parameter numbers are not CamBench's guess: every RDSTAT
        // through the guess is refused.
        Bench bench(Mc1Variant::Mc200V2, std::nullopt, {}, 0, withAxes({1, 2}, 0x2000));
        const Result<Mc1AxisDone> moved =
            bench.device.axisCommand(1, Mc1AxisCommand::MoveRelative, 100);
        QVERIFY2(moved.ok(), qPrintable(moved.error().message));
        QVERIFY(!moved->after);
        const QString problem = moved->readBackProblem;
        QVERIFY2(problem.contains(QLatin1String("parameter 4112 (0x1010), the position of axis 1")),
                 qPrintable(problem));
        QVERIFY2(problem.contains(QLatin1String("load the controller's parameter table")),
                 qPrintable(problem));
        QCOMPARE(receivedOf(bench, 0x9F).size(), 1);          // sent once
        QCOMPARE(bench.sim().axisPosition(1, 1 << 30), 100);  // it moved, once
        // STOP: acknowledged, though nothing could be read back.
        const MotionStopReport report = bench.device.motionControl()->stopAllMotion();
        QVERIFY(report.allAcknowledged());
        QVERIFY2(
            report.lines.first().detail.contains(QLatin1String("reading the axis back failed")),
            qPrintable(report.lines.first().detail));
        // With the controller's own table the values are read, not provisional.
        const Result<Mc1AxisParameterTable> table = parseMc1AxisParameterTable(
            "name,axis,parameter\nposition,1,0x2010\ntarget,1,0x2011\nstatus,1,8210\n",
            QStringLiteral("mc200.csv"));
        QVERIFY2(table.ok(), qPrintable(table.error().message));
        bench.device.setAxisParameters(*table);
        const Result<Mc1AxisState> state = bench.device.axisState(1);
        QVERIFY2(state.ok(), qPrintable(state.error().message));
        QVERIFY(!state->provisional);
        QVERIFY(!state->summary().contains(QLatin1String("provisional")));
        // Axis 2 is not in the file: refused by name, nothing sent.
        const qsizetype before = bench.sim().received().size();
        const Result<Mc1AxisState> missing = bench.device.axisState(2);
        QVERIFY2(
            missing.error().message.contains(QLatin1String("no position parameter for axis 2")),
            qPrintable(missing.error().message));
        QCOMPARE(bench.sim().received().size(), before);
    }

    void valuesReadThroughTheGuessAreMarkedProvisional() {
        Bench bench(Mc1Variant::Mc200V2);
        QVERIFY(bench.device.axisParameters().provisional);
        const Result<Mc1AxisState> state = bench.device.axisState(1);
        QVERIFY(state->provisional);
        QVERIFY2(state->summary().endsWith(QLatin1String("(provisional parameter numbers)")),
                 qPrintable(state->summary()));
    }

    void aParameterTableFileIsLoadedOrRefusedNamingItsLine_data() {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("problem");
        QTest::newRow("name") << QByteArray("position,1,100\nspeed,1,101\n")
                              << "line 2: the name must be position, target or status";
        QTest::newRow("axis") << QByteArray("# mine\n\nposition,9,100\n")
                              << "line 3: the axis must be 1 to 8, not \"9\"";
        QTest::newRow("number") << QByteArray("status,2,70000\n")
                                << "line 1: the parameter must be 0 to 65535";
        QTest::newRow("fields") << QByteArray("name,axis,parameter\nposition;1;5\n")
                                << "line 2: expected name,axis,parameter (3 fields), found 1";
        QTest::newRow("twice") << QByteArray("target,1,5\ntarget,1,6\n")
                               << "line 2: the target of axis 1 is named a second time";
        QTest::newRow("empty") << QByteArray("name,axis,parameter\n")
                               << "the file holds no parameter";
    }

    void aParameterTableFileIsLoadedOrRefusedNamingItsLine() {
        QFETCH(QByteArray, text);
        QFETCH(QString, problem);
        const Result<Mc1AxisParameterTable> table =
            parseMc1AxisParameterTable(text, QStringLiteral("bad.csv"));
        QVERIFY(!table.ok());
        QCOMPARE(table.error().kind, ErrorKind::InvalidData);
        QVERIFY2(table.error().message.contains(problem), qPrintable(table.error().message));
    }

    void anMc100HasNoAxesToStop() {
        Bench mc100(Mc1Variant::Mc100V2);
        // Not identified yet: a STOP is offered, and asking costs no telegram.
        QVERIFY(mc100.device.motionControl());
        QVERIFY(mc100.sim().received().isEmpty());
        QVERIFY(mc100.device.ensureIdentified().ok());
        QCOMPARE(mc100.device.motionControl(), nullptr);
        const Result<Mc1Axes> axes = mc100.device.axes();
        QVERIFY(axes->numbers.isEmpty());
        QVERIFY2(axes->source.contains(QLatin1String("no axis telegrams")),
                 qPrintable(axes->source));
        Bench mc200v1(Mc1Variant::Mc200V1);
        QVERIFY(mc200v1.device.ensureIdentified().ok());
        QCOMPARE(mc200v1.device.motionControl(), nullptr);
    }
};

QTEST_GUILESS_MAIN(TestMc1Motion)
#include "tst_mc1_motion.moc"
