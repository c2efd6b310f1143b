// A write's report is applied to the workspace item by item, each outcome
// paired with its item by the key it carries, never by its place in a list
// (issue 38, item 3): outcomes in another order are still each applied to
// their own item, and an item the report says nothing of stays unwritten
// and is reported as not sent, never as done.
#include "cameditor/cam_test_support.h"
#include "comm/camcon/usecases/value_text.h"
#include "ui/camcon/cameditor/cam_document.h"
#include "ui/camcon/device_writer.h"
#include "ui/camcon/workspace.h"

#include <QtTest>

#include <algorithm>

using namespace cambench;
using usecases::WriteState;

namespace {

// Program 0 and the output settings read; tracks 1 and 2 and dead times 3
// and 4 edited.
void prepare(Workspace& workspace) {
    workspace.setInfo(test::smallDevice(), true);
    CamDocument& cams = *workspace.cams();
    CamProgram program;
    program.number = 0;
    program.tracks.insert(1, Track{1, {{10, 20}}});
    program.tracks.insert(2, Track{2, {{30, 40}}});
    cams.loadProgramFromDevice(program);
    cams.loadOutputSettingsFromDevice({}, {{3, 10}, {4, 20}});
    cams.replaceTrack(0, Track{1, {{11, 21}}}, QStringLiteral("edit"));
    cams.replaceTrack(0, Track{2, {{31, 41}}}, QStringLiteral("edit"));
    cams.setDeadTime(3, 15);
    cams.setDeadTime(4, 25);
}

template <class T>
usecases::KeyedOutcome<T> written(const WorkspaceItem& item, const T& value) {
    usecases::KeyedOutcome<T> outcome;
    outcome.item = item;
    outcome.label = QStringLiteral("item");
    outcome.state = WriteState::Written;
    outcome.actual = value;
    return outcome;
}

}  // namespace

class TestWritePairing : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void outcomesInAnotherOrderGoToTheirOwnItems() {
        Workspace workspace;
        prepare(workspace);
        const PlannedWrite planned = planForItems(workspace, {});
        QCOMPARE(planned.plan.tracks.size(), 2);
        QCOMPARE(planned.plan.deadTimes.size(), 2);
        usecases::WriteReport report;
        // Reversed: by place, output 2's outcome would land on output 1.
        report.tracks << written(WorkspaceItem::track(0, 2), Track{2, {{31, 41}}})
                      << written(WorkspaceItem::track(0, 1), Track{1, {{11, 21}}});
        report.deadTimes << written(WorkspaceItem::deadTime(4), qint32(25))
                         << written(WorkspaceItem::deadTime(3), qint32(15));
        applyWriteReport(workspace, planned, report);
        const CamDocument& cams = *workspace.cams();
        QCOMPARE(cams.deviceTrack(0, 1)->cams, (QList<Cam>{{11, 21}}));
        QCOMPARE(cams.deviceTrack(0, 2)->cams, (QList<Cam>{{31, 41}}));
        QCOMPARE(cams.deviceDeadTime(3), std::optional<qint32>(15));
        QCOMPARE(cams.deviceDeadTime(4), std::optional<qint32>(25));
        QCOMPARE(workspace.changedCount(), 0);
        QVERIFY(report.complete());
    }

    void anItemWithoutOutcomeIsNotWrittenAndSaysSo() {
        Workspace workspace;
        prepare(workspace);
        const PlannedWrite planned = planForItems(workspace, {});
        usecases::WriteReport report;
        // Output 1's outcome and dead time 3's are missing.
        report.tracks << written(WorkspaceItem::track(0, 2), Track{2, {{31, 41}}});
        report.deadTimes << written(WorkspaceItem::deadTime(4), qint32(25));
        QVERIFY(report.complete());  // as it came: it would say "done"
        applyWriteReport(workspace, planned, report);
        const CamDocument& cams = *workspace.cams();
        // The device copy of the missing items is what it was; the edits stay.
        QCOMPARE(cams.deviceTrack(0, 1)->cams, (QList<Cam>{{10, 20}}));
        QCOMPARE(cams.deviceDeadTime(3), std::optional<qint32>(10));
        QCOMPARE(cams.deviceTrack(0, 2)->cams, (QList<Cam>{{31, 41}}));
        QCOMPARE(cams.deviceDeadTime(4), std::optional<qint32>(25));
        QCOMPARE(workspace.changedCount(), 2);
        // ... and the report names them as not sent.
        QVERIFY(!report.complete());
        QCOMPARE(report.count(WriteState::NotSent), 2);
        QCOMPARE(report.count(WriteState::Written), 2);
        const QList<usecases::OutcomeLine> lines = report.lines();
        const auto notSent = [&lines](const QString& label) {
            return std::any_of(lines.cbegin(), lines.cend(), [&label](const auto& line) {
                return line.label == label && line.state == WriteState::NotSent;
            });
        };
        QVERIFY(notSent(usecases::trackLabel(0, 1)));
        QVERIFY(notSent(usecases::deadTimeLabel(3)));
    }

    void aMissingSingleItemIsNotWrittenEither() {
        Workspace workspace;
        workspace.setInfo(test::smallDevice(), true);
        workspace.eepromLock().merge(true, ValueSource::Device, false);
        workspace.eepromLock().edit(false);
        const PlannedWrite planned = planForItems(workspace, {});
        QVERIFY(planned.plan.eepromLock);
        usecases::WriteReport report;
        applyWriteReport(workspace, planned, report);
        QVERIFY(report.eepromLock);
        QCOMPARE(report.eepromLock->state, WriteState::NotSent);
        QVERIFY(!report.complete());
        QCOMPARE(workspace.eepromLock().deviceValue(), std::optional<bool>(true));
        QVERIFY(workspace.eepromLock().isChanged());
    }
};

QTEST_MAIN(TestWritePairing)
#include "tst_write_pairing.moc"
