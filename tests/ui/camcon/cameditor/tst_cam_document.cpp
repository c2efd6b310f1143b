// The edit state behind the cam editor: undo commands, change tracking,
// compare with device, the multi-cam generator and the table models.
#include "cam_test_support.h"

#include "model/camcon/cam_axis.h"
#include "ui/camcon/cameditor/cam_commands.h"
#include "ui/camcon/cameditor/cam_generator.h"
#include "ui/camcon/cameditor/cam_table_model.h"
#include "ui/camcon/cameditor/editor_colors.h"
#include "ui/camcon/cameditor/track_table_model.h"

#include <QAbstractItemModelTester>
#include <QBrush>
#include <QFont>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <algorithm>

using namespace cambench;

class CamDocumentTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void setCamChangesTrackAndUndoRestoresIt();
    void setCamKeepsTrackOrderedBySwitchOnPoint();
    void repeatedEditsOfOneCellMergeIntoOneCommand();
    void editsOfDifferentCellsStaySeparate();
    void compareListsChangedTrackAndMarkWrittenClearsIt();
    void neverReadProgramIsNotRead();
    void deviceTrackAfterWriteKeepsOtherEditsAndUndo();
    void trackCutOffByAPulledCableAloneTurnsUnknown();
    void anotherDeviceForgetsCopiesAndKeepsOnlyEdits();
    void takingTheDevicesProgramIsOneUndoStep();
    void keepingMineUpdatesOnlyTheDeviceCopy();
    void copyProgramIsOneUndoStep();
    void copyTrackReplacesTargetOutput();
    void namesAndDeadTimesAreUndoable();
    void suggestedCamFitsIntoGap();
    void generatorLengthAndPitch();
    void generatorCountAndDuty();
    void generatorWrapsOnRotaryAxis();
    void generatorStopsAtLinearEnd();
    void generatorRejectsOverlappingSettings();
    void generatorRefusesMoreCamsThanATrackHolds();
    void wrappingCamIsTwoPieces();
    void linearShiftKeepsLengthAtTheEnd();
    void camTableEditGoesThroughUndoStack();
    void camTableRejectsValueOutsideRange();
    void overlappingCamsGiveRedCellNamingOtherCam();
    void camTableFollowsInsertAndDelete();
    void trackTableShowsDeadTimeAndState();
    void trackTableEditsNameAndDeadTime();
    void editedDeadTimeOrNameMarksTheRowEdited();
};

void CamDocumentTest::setCamChangesTrackAndUndoRestoresIt() {
    CamDocument document;
    test::loadDemo(document);
    QSignalSpy changed(&document, &CamDocument::trackChanged);
    document.setCam(0, 1, 1, {110, 170});
    QCOMPARE(document.track(0, 1).cams, (QList<Cam>{{20, 60}, {110, 170}}));
    QCOMPARE(changed.count(), 1);
    QCOMPARE(changed.at(0).at(1).toInt(), 1);
    document.undoStack()->undo();
    QCOMPARE(document.track(0, 1).cams, (QList<Cam>{{20, 60}, {100, 150}}));
    document.undoStack()->redo();
    QCOMPARE(document.track(0, 1).cams.at(1), (Cam{110, 170}));
}

void CamDocumentTest::setCamKeepsTrackOrderedBySwitchOnPoint() {
    CamDocument document;
    test::loadDemo(document);
    document.setCam(0, 1, 1, {5, 10});
    QCOMPARE(document.track(0, 1).cams, (QList<Cam>{{5, 10}, {20, 60}}));
}

void CamDocumentTest::repeatedEditsOfOneCellMergeIntoOneCommand() {
    CamDocument document;
    test::loadDemo(document);
    const quint64 key = SetCamCommand::cellKey(0, 1, 1, CamTableModel::OffColumn);
    document.setCam(0, 1, 1, {100, 151}, key);
    document.setCam(0, 1, 1, {100, 152}, key);
    document.setCam(0, 1, 1, {100, 153}, key);
    QCOMPARE(document.undoStack()->count(), 1);
    document.undoStack()->undo();
    QCOMPARE(document.track(0, 1).cams.at(1), (Cam{100, 150}));
}

void CamDocumentTest::editsOfDifferentCellsStaySeparate() {
    CamDocument document;
    test::loadDemo(document);
    document.setCam(0, 1, 1, {100, 151}, SetCamCommand::cellKey(0, 1, 1, 1));
    document.setCam(0, 1, 1, {101, 151}, SetCamCommand::cellKey(0, 1, 1, 0));
    document.setCam(0, 1, 0, {21, 60});  // no key: never merges
    QCOMPARE(document.undoStack()->count(), 3);
}

void CamDocumentTest::compareListsChangedTrackAndMarkWrittenClearsIt() {
    CamDocument document;
    test::loadDemo(document);
    QVERIFY(document.differences().isEmpty());
    QCOMPARE(document.changedCount(), 0);
    QSignalSpy count(&document, &CamDocument::changedCountChanged);

    document.setCam(0, 3, 0, {340, 40});
    const QList<TrackDifference> differences = document.differences();
    QCOMPARE(differences.size(), 1);
    QCOMPARE(differences.at(0).program, 0);
    QCOMPARE(differences.at(0).output, 3);
    QVERIFY(differences.at(0).deviceKnown);
    QCOMPARE(differences.at(0).deviceTrack.cams, (QList<Cam>{{330, 30}}));
    QCOMPARE(differences.at(0).editedTrack.cams, (QList<Cam>{{340, 40}}));
    QCOMPARE(document.trackState(0, 3), ChangeState::Edited);
    QCOMPARE(document.camState(0, 3, 0), ChangeState::Edited);
    QCOMPARE(document.camState(0, 1, 0), ChangeState::Unchanged);
    QCOMPARE(document.changedCount(), 1);
    QCOMPARE(count.count(), 1);

    document.setDeviceProgram(document.program(0));
    QVERIFY(document.differences().isEmpty());
    QCOMPARE(document.trackState(0, 3), ChangeState::Unchanged);
    QCOMPARE(document.changedCount(), 0);
    QCOMPARE(count.count(), 2);
}

void CamDocumentTest::neverReadProgramIsNotRead() {
    CamDocument document;
    test::loadDemo(document);
    document.insertCam(2, 5, {10, 20});
    QCOMPARE(document.trackState(2, 5), ChangeState::NotRead);
    QCOMPARE(document.programState(2), ChangeState::NotRead);
    const QList<TrackDifference> differences = document.differences();
    QCOMPARE(differences.size(), 1);
    QCOMPARE(differences.at(0).program, 2);
    QVERIFY(!differences.at(0).deviceKnown);
    QVERIFY(differences.at(0).deviceTrack.cams.isEmpty());
}

void CamDocumentTest::deviceTrackAfterWriteKeepsOtherEditsAndUndo() {
    CamDocument document;
    test::loadDemo(document);
    document.setCam(0, 1, 0, {25, 60});
    document.setCam(0, 3, 0, {300, 20});
    document.setProgramName(0, QStringLiteral("New"));
    QCOMPARE(document.changedCount(), 3);
    document.setDeviceTrack(0, document.track(0, 3));
    QCOMPARE(document.trackState(0, 3), ChangeState::Unchanged);
    QCOMPARE(document.trackState(0, 1), ChangeState::Edited);
    QCOMPARE(document.changedCount(), 2);
    document.setDeviceProgramName(0, document.programName(0));
    QCOMPARE(document.changedCount(), 1);
    QCOMPARE(document.undoStack()->count(), 3);
}

void CamDocumentTest::trackCutOffByAPulledCableAloneTurnsUnknown() {
    // Issue 12, point 8: after a cable pull mid-write only the output whose
    // write was cut off is unknown; the others keep what the report said.
    CamDocument document;
    test::loadDemo(document);
    document.setCam(0, 1, 0, {25, 60});
    document.setCam(0, 3, 0, {300, 20});
    QCOMPARE(document.changedCount(), 2);
    document.setDeviceTrack(0, document.track(0, 1));  // written
    document.forgetDeviceTrack(0, 3);                  // cut off: state unknown
    QCOMPARE(document.trackState(0, 1), ChangeState::Unchanged);
    QCOMPARE(document.trackState(0, 3), ChangeState::NotRead);
    QCOMPARE(document.trackState(0, 2), ChangeState::Unchanged);
    QVERIFY(document.hasDeviceCopy(0));
    QVERIFY(!document.deviceTrack(0, 3).has_value());
    QCOMPARE(document.changedCount(), 1);
    QCOMPARE(document.track(0, 3).cams.first(), (Cam{300, 20}));  // the edit stays
    // Read or written again: known again.
    document.setDeviceTrack(0, document.track(0, 3));
    QCOMPARE(document.trackState(0, 3), ChangeState::Unchanged);
    QCOMPARE(document.changedCount(), 0);
}

void CamDocumentTest::anotherDeviceForgetsCopiesAndKeepsOnlyEdits() {
    // Issue 12, point 3: nothing read from the old device stays as if it
    // were on the new one; what the user edited stays.
    CamDocument document;
    test::loadDemo(document);
    document.setCam(0, 1, 0, {25, 60});
    const Track edited = document.track(0, 1);
    const Track unedited = document.track(0, 3);
    QVERIFY(!unedited.cams.isEmpty());
    document.forgetDeviceCopies();
    QVERIFY(!document.hasDeviceCopy(0));
    QCOMPARE(document.track(0, 1).cams, edited.cams);
    QCOMPARE(document.trackState(0, 1), ChangeState::NotRead);
    QVERIFY(!document.deviceTrack(0, 3).has_value());
}

void CamDocumentTest::takingTheDevicesProgramIsOneUndoStep() {
    CamDocument document;
    test::loadDemo(document);
    document.setCam(0, 1, 0, {25, 60});
    document.loadProgramFromDevice(test::demoProgram());
    QCOMPARE(document.track(0, 1).cams.at(0), (Cam{20, 60}));
    QCOMPARE(document.changedCount(), 0);
    // The edit is not lost: one undo brings it back, as an edit.
    QCOMPARE(document.undoStack()->count(), 2);
    document.undoStack()->undo();
    QCOMPARE(document.track(0, 1).cams.at(0), (Cam{25, 60}));
    QCOMPARE(document.trackState(0, 1), ChangeState::Edited);
}

void CamDocumentTest::keepingMineUpdatesOnlyTheDeviceCopy() {
    CamDocument document;
    test::loadDemo(document);
    document.setCam(0, 1, 0, {25, 60});
    CamProgram device = test::demoProgram();
    device.tracks[3].cams = {{100, 200}};
    document.setDeviceProgram(device);
    QCOMPARE(document.track(0, 1).cams.at(0), (Cam{25, 60}));
    QCOMPARE(document.deviceTrack(0, 3)->cams, (QList<Cam>{{100, 200}}));
    // Output 3 was not edited here, but the PC copy is what the user sees.
    QCOMPARE(document.trackState(0, 3), ChangeState::Edited);
    QCOMPARE(document.undoStack()->count(), 1);
}

void CamDocumentTest::copyProgramIsOneUndoStep() {
    CamDocument document;
    test::loadDemo(document);
    document.copyProgram(0, 2);
    QCOMPARE(document.undoStack()->count(), 1);
    QCOMPARE(document.program(2).tracks, test::demoProgram().tracks);
    QCOMPARE(document.programName(2), QStringLiteral("Demo"));
    document.undoStack()->undo();
    QVERIFY(document.program(2).tracks.isEmpty());
}

void CamDocumentTest::copyTrackReplacesTargetOutput() {
    CamDocument document;
    test::loadDemo(document);
    document.copyTrack(0, 1, 0, 3);
    QCOMPARE(document.track(0, 3).cams, document.track(0, 1).cams);
    QCOMPARE(document.track(0, 3).output, 3);
    document.undoStack()->undo();
    QCOMPARE(document.track(0, 3).cams, (QList<Cam>{{330, 30}}));
}

void CamDocumentTest::namesAndDeadTimesAreUndoable() {
    CamDocument document;
    test::loadDemo(document);
    document.setProgramName(0, QStringLiteral("Press"));
    document.setOutputName(2, QStringLiteral("Valve"));
    document.setDeadTime(2, 123);
    QCOMPARE(document.programName(0), QStringLiteral("Press"));
    QCOMPARE(document.outputName(2), QStringLiteral("Valve"));
    QCOMPARE(document.deadTime(2), 123);
    QCOMPARE(document.changedCount(), 3);
    document.undoStack()->undo();
    document.undoStack()->undo();
    document.undoStack()->undo();
    QCOMPARE(document.programName(0), QStringLiteral("Demo"));
    QVERIFY(document.outputName(2).isEmpty());
    QCOMPARE(document.deadTime(2), 0);
}

void CamDocumentTest::suggestedCamFitsIntoGap() {
    CamDocument document;
    test::loadDemo(document);
    const Cam cam = document.suggestNewCam(0, 1);
    document.insertCam(0, 1, cam);
    QCOMPARE(document.track(0, 1).cams.size(), 3);
    QVERIFY2(document.problems(0, 1).isEmpty(),
             qPrintable(document.problems(0, 1).value(0).message));
}

void CamDocumentTest::generatorLengthAndPitch() {
    CamGeneratorSettings settings;
    settings.start = 10;
    settings.length = 20;
    settings.pitch = 90;
    const Result<QList<Cam>> cams = CamGenerator::generate(settings, 0, 359, true);
    QVERIFY(cams.ok());
    QCOMPARE(cams.value(), (QList<Cam>{{10, 30}, {100, 120}, {190, 210}, {280, 300}}));
}

void CamDocumentTest::generatorCountAndDuty() {
    CamGeneratorSettings settings;
    settings.mode = CamGeneratorSettings::Mode::CountAndDuty;
    settings.start = 0;
    settings.count = 3;
    settings.dutyPercent = 50;
    const Result<QList<Cam>> cams = CamGenerator::generate(settings, 0, 359, true);
    QVERIFY(cams.ok());
    QCOMPARE(cams.value(), (QList<Cam>{{0, 60}, {120, 180}, {240, 300}}));
}

void CamDocumentTest::generatorWrapsOnRotaryAxis() {
    CamGeneratorSettings settings;
    settings.start = 300;
    settings.length = 90;
    settings.pitch = 120;
    const Result<QList<Cam>> cams = CamGenerator::generate(settings, 0, 359, true);
    QVERIFY(cams.ok());
    QCOMPARE(cams.value(), (QList<Cam>{{300, 30}, {60, 150}, {180, 270}}));
    const Track track{1, cams.value()};
    QVERIFY(validateTrack(track, 0, test::smallDevice(), true).isEmpty());
}

void CamDocumentTest::generatorStopsAtLinearEnd() {
    CamGeneratorSettings settings;
    settings.start = 0;
    settings.length = 10;
    settings.pitch = 30;
    const Result<QList<Cam>> cams = CamGenerator::generate(settings, 0, 100, false);
    QVERIFY(cams.ok());
    QCOMPARE(cams.value(), (QList<Cam>{{0, 10}, {30, 40}, {60, 70}, {90, 100}}));
}

void CamDocumentTest::generatorRejectsOverlappingSettings() {
    CamGeneratorSettings settings;
    settings.length = 30;
    settings.pitch = 30;
    const Result<QList<Cam>> cams = CamGenerator::generate(settings, 0, 359, true);
    QVERIFY(!cams.ok());
    QCOMPARE(cams.error().kind, ErrorKind::InvalidData);
    QVERIFY(cams.error().message.contains(QStringLiteral("pitch")));
}

void CamDocumentTest::generatorRefusesMoreCamsThanATrackHolds() {
    CamGeneratorSettings settings;
    settings.length = 1;
    settings.pitch = 2;
    const Result<QList<Cam>> cams = CamGenerator::generate(settings, 0, 2000000000, true);
    QVERIFY(!cams.ok());
    QVERIFY(cams.error().message.contains(QString::number(kMaxCamsPerTrack)));
}

void CamDocumentTest::wrappingCamIsTwoPieces() {
    const Axis axis{0, 359, true};
    const QList<CamPiece> pieces = camPieces({330, 30}, axis);
    QCOMPARE(pieces.size(), 2);
    QCOMPARE(pieces.at(0).from, 330);
    QCOMPARE(pieces.at(0).to, 360);
    QCOMPARE(pieces.at(1).from, 0);
    QCOMPARE(pieces.at(1).to, 30);
    QCOMPARE(axis.length({330, 30}), 60);
    QCOMPARE(camPieces({20, 60}, axis).size(), 1);
}

void CamDocumentTest::linearShiftKeepsLengthAtTheEnd() {
    const Axis axis{0, 100, false};
    QCOMPARE(axis.shifted({80, 95}, 20), (Cam{85, 100}));
    QCOMPARE(axis.shifted({5, 15}, -20), (Cam{0, 10}));
    const Axis rotary{0, 359, true};
    QCOMPARE(rotary.shifted({340, 350}, 30), (Cam{10, 20}));
}

void CamDocumentTest::camTableEditGoesThroughUndoStack() {
    CamDocument document;
    test::loadDemo(document);
    CamTableModel model(&document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    model.setTrack(0, 1);
    QCOMPARE(model.rowCount(), 2);
    QVERIFY(model.setData(model.index(1, CamTableModel::OffColumn), 170));
    QCOMPARE(document.track(0, 1).cams.at(1), (Cam{100, 170}));
    QCOMPARE(model.index(1, CamTableModel::LengthColumn).data().toLongLong(), 70);
    QVERIFY(model.setData(model.index(1, CamTableModel::LengthColumn), 30));
    QCOMPARE(document.track(0, 1).cams.at(1), (Cam{100, 130}));
    QCOMPARE(document.undoStack()->count(), 2);
    document.undoStack()->undo();
    document.undoStack()->undo();
    QCOMPARE(model.index(1, CamTableModel::OffColumn).data().toInt(), 150);
}

void CamDocumentTest::camTableRejectsValueOutsideRange() {
    CamDocument document;
    test::loadDemo(document);
    CamTableModel model(&document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    model.setTrack(0, 1);
    QVERIFY(!model.setData(model.index(0, CamTableModel::OnColumn), 360));
    QVERIFY(!model.setData(model.index(0, CamTableModel::OnColumn), QStringLiteral("x")));
    QCOMPARE(document.undoStack()->count(), 0);
}

void CamDocumentTest::overlappingCamsGiveRedCellNamingOtherCam() {
    CamDocument document;
    test::loadDemo(document);
    CamTableModel model(&document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    model.setTrack(0, 1);
    QVERIFY(!model.index(1, CamTableModel::OnColumn).data(Qt::BackgroundRole).isValid());
    // Cam 2 now starts inside cam 1 (20..60).
    QVERIFY(model.setData(model.index(1, CamTableModel::OnColumn), 50));
    const QModelIndex cell = model.index(1, CamTableModel::OnColumn);
    QCOMPARE(cell.data(Qt::BackgroundRole).value<QBrush>().color(), errorColor());
    const QString tip = cell.data(Qt::ToolTipRole).toString();
    QVERIFY2(tip.contains(QStringLiteral("overlaps cam 1")), qPrintable(tip));
    QCOMPARE(cell.data(Qt::StatusTipRole).toString(), tip);
    QVERIFY(!model.index(0, CamTableModel::OnColumn).data(Qt::BackgroundRole).isValid());
    document.undoStack()->undo();
    QVERIFY(!model.index(1, CamTableModel::OnColumn).data(Qt::BackgroundRole).isValid());
}

void CamDocumentTest::camTableFollowsInsertAndDelete() {
    CamDocument document;
    test::loadDemo(document);
    CamTableModel model(&document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    model.setTrack(0, 1);
    document.insertCam(0, 1, {200, 220});
    QCOMPARE(model.rowCount(), 3);
    QCOMPARE(model.index(2, CamTableModel::OnColumn).data().toInt(), 200);
    document.deleteCam(0, 1, 0);
    QCOMPARE(model.rowCount(), 2);
    QCOMPARE(model.index(0, CamTableModel::OnColumn).data().toInt(), 100);
    model.setTrack(0, 2);
    QCOMPARE(model.rowCount(), 0);
}

void CamDocumentTest::trackTableShowsDeadTimeAndState() {
    CamDocument document;
    test::loadDemo(document);
    TrackTableModel model(&document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    QCOMPARE(model.rowCount(), 8);
    QCOMPARE(model.columnCount(), int(TrackTableModel::COUNT));
    document.loadOutputSettingsFromDevice({{1, QStringLiteral("Glue")}}, {{1, 123}});
    QCOMPARE(model.index(0, TrackTableModel::NameColumn).data().toString(), QStringLiteral("Glue"));
    QCOMPARE(model.index(0, TrackTableModel::DeadTimeColumn).data().toString(),
             QStringLiteral("12.3 ms"));
    QCOMPARE(model.index(0, TrackTableModel::CamCountColumn).data().toInt(), 2);
    const QModelIndex state = model.index(2, TrackTableModel::StateColumn);
    QCOMPARE(state.data().toString(), QStringLiteral("unchanged"));
    document.setCam(0, 3, 0, {300, 30});
    QCOMPARE(state.data().toString(), QStringLiteral("edited"));
    document.setDeviceProgram(document.program(0));
    QCOMPARE(state.data().toString(), QStringLiteral("unchanged"));
    model.setProgram(1);
    QCOMPARE(state.data().toString(), QStringLiteral("not read"));
    // A smaller device shrinks the table.
    DeviceInfo info = test::smallDevice();
    info.outputs = 16;
    document.setLimits(info, true);
    QCOMPARE(model.rowCount(), 16);
}

void CamDocumentTest::trackTableEditsNameAndDeadTime() {
    CamDocument document;
    test::loadDemo(document);
    TrackTableModel model(&document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    QVERIFY(model.setData(model.index(1, TrackTableModel::NameColumn), QStringLiteral("Knife")));
    QCOMPARE(document.outputName(2), QStringLiteral("Knife"));
    QVERIFY(!model.setData(model.index(1, TrackTableModel::NameColumn),
                           QStringLiteral("a name that is far too long")));
    QVERIFY(model.setData(model.index(1, TrackTableModel::DeadTimeColumn), 4.5));
    QCOMPARE(document.deadTime(2), 45);
    QVERIFY(!model.setData(model.index(1, TrackTableModel::DeadTimeColumn), 5000.0));
    QCOMPARE(document.undoStack()->count(), 2);
}

// The row's state is the output's as a whole: an edited dead time (or name)
// beside cams equal to the device's is "edited" (it will be written), and
// the tooltip says which part; writing it back makes the row "unchanged".
void CamDocumentTest::editedDeadTimeOrNameMarksTheRowEdited() {
    CamDocument document;
    test::loadDemo(document);
    document.setDeviceProgram(document.program(0));
    document.loadOutputSettingsFromDevice({{2, QStringLiteral("Knife")}}, {{2, 40}});
    TrackTableModel model(&document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    const QModelIndex state = model.index(1, TrackTableModel::StateColumn);
    QCOMPARE(state.data().toString(), QStringLiteral("unchanged"));
    QCOMPARE(state.data(Qt::ToolTipRole).toString(),
             QStringLiteral("Output 2 is the same as on the device."));

    QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
    QVERIFY(model.setData(model.index(1, TrackTableModel::DeadTimeColumn), 4.5));
    QCOMPARE(state.data().toString(), QStringLiteral("edited"));
    QVERIFY(
        state.data(Qt::ToolTipRole).toString().contains(QStringLiteral("dead time of output 2")));
    QVERIFY(
        model.index(1, TrackTableModel::DeadTimeColumn).data(Qt::FontRole).value<QFont>().bold());
    QVERIFY(!model.index(1, TrackTableModel::NameColumn).data(Qt::FontRole).value<QFont>().bold());
    // The view hears of the state column too, not only of the dead time cell.
    const bool stateAnnounced =
        std::any_of(changed.cbegin(), changed.cend(), [](const QList<QVariant>& args) {
            return args.at(1).toModelIndex().column() >= TrackTableModel::StateColumn;
        });
    QVERIFY(stateAnnounced);
    // Another output stays as it was.
    QCOMPARE(model.index(2, TrackTableModel::StateColumn).data().toString(),
             QStringLiteral("unchanged"));

    document.setDeviceDeadTime(2, 45);
    QCOMPARE(state.data().toString(), QStringLiteral("unchanged"));
    QVERIFY(model.setData(model.index(1, TrackTableModel::NameColumn), QStringLiteral("Glue")));
    QCOMPARE(state.data().toString(), QStringLiteral("edited"));
    QVERIFY(state.data(Qt::ToolTipRole).toString().contains(QStringLiteral("name of output 2")));
}

QTEST_MAIN(CamDocumentTest)
#include "tst_cam_document.moc"
