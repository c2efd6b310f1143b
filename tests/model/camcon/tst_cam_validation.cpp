#include "model/camcon/cam_validation.h"

#include <QtTest>

using namespace cambench;

namespace {

DeviceInfo rotaryDevice() {
    DeviceInfo device;
    device.minPosition = 0;
    device.maxPosition = 359;
    device.outputs = 32;
    device.programs = 16;
    return device;
}

Track track(int output, QList<Cam> cams) {
    Track t;
    t.output = output;
    t.cams = std::move(cams);
    return t;
}

QStringList messages(const QList<CamProblem>& problems) {
    QStringList list;
    for (const CamProblem& p : problems) list << p.message;
    return list;
}

}  // namespace

class TestCamValidation : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void validTrackHasNoProblems() {
        const Track t = track(5, {{10, 50}, {100, 200}, {300, 5}});
        QVERIFY(validateTrack(t, 3, rotaryDevice(), true).isEmpty());
    }

    void pointAboveMaximumNamesProgramOutputAndCam() {
        const Track t = track(5, {{10, 50}, {300, 400}});
        const QList<CamProblem> problems = validateTrack(t, 3, rotaryDevice(), true);
        QCOMPARE(problems.size(), 1);
        QCOMPARE(problems.first().program, 3);
        QCOMPARE(problems.first().output, 5);
        QCOMPARE(problems.first().cam, 1);
        QCOMPARE(problems.first().message,
                 QStringLiteral("program 3, output 5, cam 2: switch-off point 400 is above "
                                "the maximum 359"));
    }

    void pointBelowMinimumIsReported() {
        DeviceInfo device = rotaryDevice();
        device.minPosition = 100;
        const QList<CamProblem> problems = validateTrack(track(1, {{50, 150}}), 0, device, true);
        QCOMPARE(problems.size(), 1);
        QVERIFY(problems.first().message.contains(
            QStringLiteral("switch-on point 50 is below the minimum 100")));
    }

    void equalPointsAreAnError() {
        const QList<CamProblem> problems =
            validateTrack(track(1, {{40, 40}}), 0, rotaryDevice(), true);
        QCOMPARE(problems.size(), 1);
        QCOMPARE(problems.first().cam, 0);
        QVERIFY(problems.first().message.contains(QStringLiteral("both 40")));
    }

    void wrapAroundIsAnErrorOnLinearAxis() {
        const Track t = track(1, {{300, 20}});
        QVERIFY(validateTrack(t, 0, rotaryDevice(), true).isEmpty());
        const QList<CamProblem> problems = validateTrack(t, 0, rotaryDevice(), false);
        QCOMPARE(problems.size(), 1);
        QVERIFY(problems.first().message.contains(QStringLiteral("rotary")));
    }

    void overlapIsReportedWithBothCams() {
        const QList<CamProblem> problems =
            validateTrack(track(2, {{10, 50}, {40, 80}}), 1, rotaryDevice(), true);
        QCOMPARE(problems.size(), 1);
        QCOMPARE(problems.first().cam, 1);
        QCOMPARE(problems.first().message,
                 QStringLiteral("program 1, output 2, cam 2: 40..80 overlaps cam 1 (10..50)"));
    }

    void wrapAroundCamOverlapsCamAfterZero() {
        // [300,20] covers 300..359 and 0..19, so it overlaps [10,50].
        const QList<CamProblem> problems =
            validateTrack(track(1, {{300, 20}, {10, 50}}), 0, rotaryDevice(), true);
        QCOMPARE(problems.size(), 1);
        QVERIFY(problems.first().message.contains(QStringLiteral("overlaps")));
    }

    void wrapAroundCamOverlapsCamBeforeMaximum() {
        const QList<CamProblem> problems =
            validateTrack(track(1, {{350, 355}, {300, 20}}), 0, rotaryDevice(), true);
        QCOMPARE(problems.size(), 1);
    }

    void touchingCamsDoNotOverlap() {
        // The switch-off point is the first position that is off again.
        QVERIFY(validateTrack(track(1, {{300, 20}, {20, 40}}), 0, rotaryDevice(), true).isEmpty());
        QVERIFY(validateTrack(track(1, {{10, 20}, {20, 30}}), 0, rotaryDevice(), false).isEmpty());
        QVERIFY(
            validateTrack(track(1, {{100, 300}, {300, 100}}), 0, rotaryDevice(), true).isEmpty());
    }

    void twoWrapAroundCamsOverlap() {
        QCOMPARE(validateTrack(track(1, {{300, 20}, {350, 10}}), 0, rotaryDevice(), true).size(),
                 1);
    }

    void camInsideAnotherOverlaps() {
        QCOMPARE(
            validateTrack(track(1, {{0, 300}, {100, 110}, {200, 210}}), 0, rotaryDevice(), true)
                .size(),
            2);
    }

    void tooManyCamsPerTrack() {
        QList<Cam> cams;
        for (int i = 0; i < kMaxCamsPerTrack + 1; ++i) cams << Cam{i * 2, i * 2 + 1};
        DeviceInfo device = rotaryDevice();
        device.maxPosition = 1000;
        QVERIFY(validateTrack(track(1, cams.mid(0, kMaxCamsPerTrack)), 0, device, true).isEmpty());
        const QList<CamProblem> problems = validateTrack(track(1, cams), 0, device, true);
        QCOMPARE(problems.size(), 1);
        QCOMPARE(problems.first().cam, -1);
        QVERIFY(problems.first().message.contains(QStringLiteral("at most 125")));
    }

    void outputOutsideDeviceRange() {
        QCOMPARE(validateTrack(track(0, {{1, 2}}), 0, rotaryDevice(), true).size(), 1);
        const QList<CamProblem> problems =
            validateTrack(track(33, {{1, 2}}), 0, rotaryDevice(), true);
        QCOMPARE(problems.size(), 1);
        QCOMPARE(problems.first().message,
                 QStringLiteral("program 0, output 33: the device has outputs 1..32"));
        QVERIFY(validateTrack(track(32, {{1, 2}}), 0, rotaryDevice(), true).isEmpty());
    }

    void programOutsideDeviceRange() {
        CamProgram program;
        program.number = 16;
        QCOMPARE(messages(validateProgram(program, rotaryDevice(), true)),
                 QStringList{QStringLiteral("program 16: the device has programs 0..15")});
        program.number = -1;
        QCOMPARE(validateProgram(program, rotaryDevice(), true).size(), 1);
        program.number = 15;
        QVERIFY(validateProgram(program, rotaryDevice(), true).isEmpty());
    }

    void programChecksEveryTrackAndItsKey() {
        CamProgram program;
        program.number = 2;
        program.tracks.insert(1, track(1, {{10, 20}, {15, 30}}));
        program.tracks.insert(4, track(3, {{10, 20}}));
        const QList<CamProblem> problems = validateProgram(program, rotaryDevice(), true);
        QCOMPARE(problems.size(), 2);
        QCOMPARE(problems.at(0).output, 1);
        QVERIFY(problems.at(1).message.contains(QStringLiteral("output 4")));
    }

    void camCoversHalfOpenRange() {
        const Cam normal{10, 50};
        QVERIFY(!camCovers(normal, 9));
        QVERIFY(camCovers(normal, 10));
        QVERIFY(camCovers(normal, 49));
        QVERIFY(!camCovers(normal, 50));
        const Cam wrap{300, 20};
        QVERIFY(camCovers(wrap, 300));
        QVERIFY(camCovers(wrap, 359));
        QVERIFY(camCovers(wrap, 0));
        QVERIFY(camCovers(wrap, 19));
        QVERIFY(!camCovers(wrap, 20));
        QVERIFY(!camCovers(wrap, 299));
    }

    void trackActiveAtAnyCam() {
        const Track t = track(1, {{10, 20}, {300, 5}});
        QVERIFY(trackActiveAt(t, 15));
        QVERIFY(trackActiveAt(t, 2));
        QVERIFY(!trackActiveAt(t, 25));
        QVERIFY(!trackActiveAt(Track{}, 0));
    }

    void normaliseSortsBySwitchOnAndDropsEmptyTracks() {
        CamProgram program;
        program.tracks.insert(1, track(1, {{300, 20}, {10, 50}, {100, 120}}));
        program.tracks.insert(2, track(2, {}));
        normaliseProgram(program);
        QCOMPARE(program.tracks.keys(), QList<int>{1});
        QCOMPARE(program.tracks.value(1).cams, (QList<Cam>{{10, 50}, {100, 120}, {300, 20}}));
    }
};

QTEST_GUILESS_MAIN(TestCamValidation)
#include "tst_cam_validation.moc"
