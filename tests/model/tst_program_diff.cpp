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
