// Issue 17, point 2: where cams switch electrically at speed, against hand
// computed cases (a rotary axis 0..359 at 60 1/min runs 360 positions/s).
#include "model/camcon/cam_timing.h"

#include <QTest>

using namespace cambench;

namespace {

const Axis kRotary{0, 359, true};
const Axis kLinear{0, 9999, false};

Track track(int output, const QList<Cam>& cams) {
    return {output, cams};
}

OutputDeadTime normal(qint32 tenthsMs) {
    return {DeadTimeMode::Normal, tenthsMs, 0, 0};
}

OutputDeadTime separate(qint32 onTenthsMs, qint32 offTenthsMs) {
    return {DeadTimeMode::SeparateOnOff, 0, onTenthsMs, offTenthsMs};
}

bool near(double a, double b) {
    return std::abs(a - b) < 1e-6;
}

}  // namespace

class TestCamTiming : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void speedUnits() {
        QVERIFY(near(toPositionsPerSecond(60, kRotary), 360));
        QVERIFY(near(fromPositionsPerSecond(360, kRotary), 60));
        QVERIFY(near(toPositionsPerSecond(250, kLinear), 250));
        QCOMPARE(speedUnit(kRotary), QStringLiteral("1/min"));
        QCOMPARE(speedUnit(kLinear), QStringLiteral("pos/s"));
    }

    void plainDeadTimeShiftsBothEdges() {
        // 10 ms at 360 positions/s: 3.6 positions early, the length stays.
        const OutputTiming t = timeTrack(track(1, {{10, 90}}), normal(100), 360, kRotary);
        QVERIFY(near(t.shiftOn, 3.6));
        QVERIFY(near(t.shiftOff, 3.6));
        QCOMPARE(t.cams.size(), 1);
        QVERIFY(near(t.cams[0].on, 6.4));
        QVERIFY(near(t.cams[0].off, 86.4));
        QVERIFY(near(*t.cams[0].durationMs, 80.0 / 360 * 1000));
        QVERIFY(t.problems.isEmpty());
        // The only limit: an edge moving by a whole cycle, 360 pos in 10 ms.
        QCOMPARE(t.firstLimit->kind, TimingProblem::Kind::ShiftOverCycle);
        QVERIFY(near(t.firstLimit->fromSpeed, 36000));
        QCOMPARE(describeProblem(1, *t.firstLimit, kRotary),
                 QStringLiteral("output 1: the switch points move by more than one cycle above "
                                "6000 1/min"));
    }

    void wrapsAroundTheCycleEnd() {
        const OutputTiming t = timeTrack(track(2, {{2, 50}}), normal(100), 360, kRotary);
        QVERIFY(near(t.cams[0].on, 358.4));
        QVERIFY(near(t.cams[0].off, 46.4));
        // A cam that wraps already: 350..10 is 20 positions long.
        const OutputTiming w = timeTrack(track(2, {{350, 10}}), normal(0), 360, kRotary);
        QVERIFY(near(w.cams[0].length, 20));
        QVERIFY(near(*w.cams[0].durationMs, 20.0 / 360 * 1000));
    }

    void longerOffDeadTimeShrinksAndVanishes() {
        // on 5 ms, off 25 ms: the cam loses 20 ms worth of positions.
        const Track t3 = track(3, {{10, 20}});
        const OutputTiming t = timeTrack(t3, separate(50, 250), 360, kRotary);
        QVERIFY(near(t.cams[0].length, 10 - 7.2));
        QVERIFY(near(*t.cams[0].durationMs, 2.8 / 360 * 1000));
        QVERIFY(t.problems.isEmpty());
        QCOMPARE(t.firstLimit->kind, TimingProblem::Kind::Vanishes);
        QVERIFY(near(t.firstLimit->fromSpeed, 500));
        QCOMPARE(describeProblem(3, *t.firstLimit, kRotary),
                 QStringLiteral("output 3: cam 1 vanishes above 83.3 1/min"));
        const OutputTiming fast = timeTrack(t3, separate(50, 250), 600, kRotary);
        QCOMPARE(fast.problems.size(), 1);
        QCOMPARE(fast.problems.first().kind, TimingProblem::Kind::Vanishes);
    }

    void longerOnDeadTimeGrowsAndMerges() {
        const Track t4 = track(4, {{10, 20}, {30, 40}});
        const OutputTiming t = timeTrack(t4, separate(250, 50), 360, kRotary);
        QCOMPARE(t.firstLimit->kind, TimingProblem::Kind::Merges);
        QCOMPARE(t.firstLimit->cam, 1);
        QCOMPARE(t.firstLimit->nextCam, 2);
        QVERIFY(near(t.firstLimit->fromSpeed, 500));
        QCOMPARE(describeProblem(4, *t.firstLimit, kRotary),
                 QStringLiteral("output 4: cams 1 and 2 merge above 83.3 1/min"));
        QVERIFY(near(t.cams[0].length, 10 + 7.2));
    }

    void minimumPulse() {
        // 90 positions last less than 50 ms above 1800 positions/s.
        const Track t5 = track(5, {{0, 90}});
        const OutputTiming slow = timeTrack(t5, normal(0), 360, kRotary, 50);
        QVERIFY(slow.problems.isEmpty());
        QVERIFY(near(slow.firstLimit->fromSpeed, 1800));
        QVERIFY(near(*slow.shortestDurationMs, 250));
        const OutputTiming fast = timeTrack(t5, normal(0), 2000, kRotary, 50);
        QCOMPARE(fast.problems.size(), 1);
        QCOMPARE(fast.problems.first().kind, TimingProblem::Kind::ShortPulse);
    }

    void linearAxisNeitherWrapsNorCycles() {
        const OutputTiming t = timeTrack(track(6, {{5, 50}}), normal(100), 1000, kLinear);
        QVERIFY(near(t.cams[0].on, -5));
        QVERIFY(near(t.cams[0].off, 40));
        QVERIFY(!t.firstLimit);
    }

    void pathTimeStaysOnForTheSwitchingTime() {
        const OutputDeadTime path{DeadTimeMode::PathTime, 0, 100, 500};
        const OutputTiming t = timeTrack(track(7, {{100, 300}}), path, 360, kRotary, 60);
        QVERIFY(near(t.cams[0].on, 96.4));
        QVERIFY(near(*t.cams[0].durationMs, 50));
        QVERIFY(near(t.cams[0].length, 18));
        QCOMPARE(t.problems.size(), 1);
        QCOMPARE(describeProblem(7, t.problems.first(), kRotary),
                 QStringLiteral("output 7: cam 1 is on for less than the minimum pulse at every "
                                "speed"));
    }

    void programWithDeadTimesAndMinimumPulsesPerOutput() {
        // Plain dead times stand in as mode Normal; modes, where there are
        // any, are the device's whole answer.
        const DeadTimeModes plain = deadTimesAsModes({{1, 100}, {2, 0}}, {});
        QCOMPARE(plain.value(1), normal(100));
        const DeadTimeModes modes{{1, separate(10, 20)}};
        QCOMPARE(deadTimesAsModes({{1, 100}}, modes), modes);

        CamProgram program;
        program.tracks[1] = track(1, {{0, 90}});
        program.tracks[2] = track(2, {{0, 90}});
        program.tracks[3] = track(3, {});  // no cams: not timed
        // 2000 pos/s: 90 positions last 45 ms; only output 2 needs 50 ms.
        const QList<OutputTiming> timed = timeProgram(program, plain, 2000, kRotary, {{2, 500}});
        QCOMPARE(timed.size(), 2);
        QCOMPARE(timed[0].output, 1);
        QVERIFY(timed[0].problems.isEmpty());
        QCOMPARE(timed[1].problems.size(), 1);
        QCOMPARE(timed[1].problems.first().kind, TimingProblem::Kind::ShortPulse);
    }

    void minimumPulsesFromTheCommandLine() {
        QCOMPARE(*parseMinimumPulses(QStringLiteral("12"), 3),
                 (MinimumPulses{{1, 120}, {2, 120}, {3, 120}}));
        QCOMPARE(*parseMinimumPulses(QStringLiteral("3=12,1=8.5"), 4),
                 (MinimumPulses{{1, 85}, {3, 120}}));
        // Every output 5 ms, output 2 its own.
        QCOMPARE(*parseMinimumPulses(QStringLiteral("5, 2=20"), 3),
                 (MinimumPulses{{1, 50}, {2, 200}, {3, 50}}));
        QVERIFY(!parseMinimumPulses(QStringLiteral("8,5=2"), 4));  // output 5 of 4
        QVERIFY(!parseMinimumPulses(QStringLiteral("2=fast"), 4));
        QVERIFY(!parseMinimumPulses(QStringLiteral("-1"), 4));
        // A German decimal comma is refused, not read as "every output 5 ms".
        const auto comma = parseMinimumPulses(QStringLiteral("2=7,5"), 4);
        QVERIFY(!comma);
        QVERIFY2(comma.error().message.contains(QStringLiteral("decimal point")),
                 qPrintable(comma.error().message));
    }

    void standstillHasNoDuration() {
        const OutputTiming t = timeTrack(track(8, {{10, 20}}), normal(100), 0, kRotary, 5);
        QVERIFY(!t.cams[0].durationMs);
        QVERIFY(t.problems.isEmpty());
        QVERIFY(near(t.cams[0].on, 10));
    }
};

QTEST_APPLESS_MAIN(TestCamTiming)
#include "tst_cam_timing.moc"
