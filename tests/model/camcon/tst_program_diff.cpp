// Issue 17: what differs between two cam programs, output by output.
#include "model/camcon/program_diff.h"

#include <QTest>

using namespace cambench;

namespace {

CamProgram program(const QMap<int, QList<Cam>>& tracks, const QString& name = {}) {
    CamProgram p;
    p.name = name;
    for (auto it = tracks.cbegin(); it != tracks.cend(); ++it)
        p.tracks[it.key()] = {it.key(), it.value()};
    return p;
}

QStringList lines(const ProgramDiff& diff) {
    QStringList out;
    for (const CamDifference& d : diff.cams) out << describeDifference(d);
    return out;
}

}  // namespace

class TestProgramDiff : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void equalProgramsHaveNoDifference() {
        const CamProgram a =
            program({{1, {{10, 90}, {180, 270}}}, {3, {{5, 6}}}}, QStringLiteral("x"));
        QVERIFY(diffPrograms(a, a).isEmpty());
        // An empty track is the same as an absent one.
        CamProgram b = a;
        b.tracks[7] = {7, {}};
        QVERIFY(diffPrograms(a, b).isEmpty());
    }

    void movedEdgeIsOneChangedCam() {
        const CamProgram a = program({{3, {{10, 20}, {50, 60}}}});
        const CamProgram b = program({{3, {{12, 20}, {50, 60}}}});
        const ProgramDiff diff = diffPrograms(a, b);
        QCOMPARE(lines(diff), QStringList{QStringLiteral("output 3, cam 1: 10..20 → 12..20")});
        QCOMPARE(diff.cams.first().kind, CamDifference::Kind::Changed);
    }

    void addedAndRemovedCams() {
        const CamProgram a = program({{1, {{10, 20}}}, {2, {{100, 120}}}});
        const CamProgram b = program({{1, {{10, 20}, {200, 220}}}, {4, {{5, 9}}}});
        QCOMPARE(lines(diffPrograms(a, b)),
                 (QStringList{QStringLiteral("output 1: cam 200..220 only in B"),
                              QStringLiteral("output 2: cam 100..120 only in A"),
                              QStringLiteral("output 4: cam 5..9 only in B")}));
    }

    void camsPairByOverlapNotByNumber() {
        // A cam inserted before: the others keep their identity, only the
        // new one is reported, under B's numbering for it.
        const CamProgram a = program({{2, {{100, 150}, {200, 250}}}});
        const CamProgram b = program({{2, {{10, 20}, {100, 150}, {200, 260}}}});
        QCOMPARE(lines(diffPrograms(a, b)),
                 (QStringList{QStringLiteral("output 2: cam 10..20 only in B"),
                              QStringLiteral("output 2, cam 2 (in B 3): 200..250 → 200..260")}));
    }

    void wrappingCamsOverlapThroughZero() {
        // 350..10 wraps; 355..20 overlaps it at the cycle's end and start.
        const CamProgram a = program({{5, {{350, 10}}}});
        const CamProgram b = program({{5, {{355, 20}}}});
        QCOMPARE(lines(diffPrograms(a, b)),
                 QStringList{QStringLiteral("output 5, cam 1: 350..10 → 355..20")});
        // A cam at the start overlaps only the wrapping part.
        const CamProgram c = program({{5, {{0, 5}}}});
        QCOMPARE(diffPrograms(a, c).cams.first().kind, CamDifference::Kind::Changed);
        // Disjoint: one removed, one added.
        const CamProgram d = program({{5, {{100, 120}}}});
        QCOMPARE(diffPrograms(a, d).cams.size(), 2);
    }

    void checkedDifferencesApplyToEitherSide() {
        const CamProgram a = program({{1, {{10, 20}, {50, 60}}}, {2, {{100, 120}}}});
        const CamProgram b = program({{1, {{12, 20}, {50, 60}, {200, 220}}}, {3, {{5, 9}}}});
        const ProgramDiff diff = diffPrograms(a, b);
        QCOMPARE(diff.cams.size(), 4);  // 1 changed, 1: 200..220 in B, 2: in A, 3: in B

        // B made like A in everything: B's tracks become A's.
        const AppliedDifferences all = applyDifferences(b, DiffSide::B, diff.cams);
        QVERIFY(all.problems.isEmpty());
        QCOMPARE(all.tracks.value(1).cams, a.tracks.value(1).cams);
        QCOMPARE(all.tracks.value(2).cams, a.tracks.value(2).cams);
        QVERIFY(all.tracks.value(3).cams.isEmpty());  // removed: written empty
        QCOMPARE(all.tracks.value(3).output, 3);

        // Only the changed cam, onto A: output 1 only, its other cam kept.
        const AppliedDifferences one = applyDifferences(a, DiffSide::A, {diff.cams.first()});
        QCOMPARE(one.tracks.keys(), QList<int>{1});
        QCOMPARE(one.tracks.value(1).cams, (QList<Cam>{{12, 20}, {50, 60}}));

        // A program that no longer holds the cam: that output is refused.
        const CamProgram moved = program({{1, {{30, 40}}}});
        const AppliedDifferences stale = applyDifferences(moved, DiffSide::A, {diff.cams.first()});
        QVERIFY(stale.tracks.isEmpty());
        QCOMPARE(stale.problems.size(), 1);
    }

    void namesDiffer() {
        const ProgramDiff diff = diffPrograms(program({}, QStringLiteral("Standard")),
                                              program({}, QStringLiteral("Fast")));
        QVERIFY(diff.nameDiffers());
        QVERIFY(!diff.isEmpty());
        QVERIFY(diff.cams.isEmpty());
    }
};

QTEST_APPLESS_MAIN(TestProgramDiff)
#include "tst_program_diff.moc"
