// The workspace's sections in the one shape (SectionCopies): what a device
// change keeps with each CarryOver, the totals and the signals, and the
// dead-time modes' rule of outputs the device lacks. Two devices that
// differ, A and B.
#include "ui/camcon/cameditor/cam_document.h"
#include "ui/camcon/workspace.h"

#include <QSignalSpy>
#include <QtTest>

using namespace cambench;

namespace {

struct Device {
    SystemSettings settings;
    PlcNetwork network;
    DeadTimeModes modes;
    AnalogueCamTrack analogue;
    ProgrammingProgram programming;
    bool locked = false;
};

Device deviceA() {
    Device a;
    a.settings = {{QStringLiteral("speedFactor"), 100000}, {QStringLiteral("encoderText1"), "A"}};
    a.network.area = PlcNetwork::M;
    a.network.number = 3;
    a.network.value = 7;
    a.modes = {{1, {DeadTimeMode::Normal, 5, 0, 0}}, {2, {DeadTimeMode::PathTime, 0, 3, 9}}};
    a.analogue = {2, {{10, 100}}};
    a.programming = {4, 1, 0};
    a.locked = true;
    return a;
}

Device deviceB() {
    Device b;
    b.settings = {{QStringLiteral("speedFactor"), 50000}};
    b.network.area = PlcNetwork::M;
    b.network.number = 3;
    b.network.value = 8;
    b.modes = {{1, {DeadTimeMode::Normal, 6, 0, 0}}};  // one output only
    b.analogue = {2, {{20, 200}}};
    b.programming = {1, 0, 0};
    b.locked = true;
    return b;
}

// What a read of everything puts into the sections.
void read(Workspace& workspace, const Device& device, bool keepEdits) {
    workspace.settings().mergeWhole(device.settings, keepEdits);
    workspace.plc().merge(Workspace::plcByKey({device.network}), ValueSource::Device, keepEdits);
    workspace.mergeDeadTimeModes(device.modes, ValueSource::Device, keepEdits);
    workspace.analogueCams().merge({{device.analogue.output, device.analogue}}, ValueSource::Device,
                                   keepEdits);
    workspace.programmingProgram().merge(device.programming, ValueSource::Device, keepEdits);
    workspace.eepromLock().merge(device.locked, ValueSource::Device, keepEdits);
}

// One edit in each section.
void editEach(Workspace& workspace) {
    workspace.settings().edit(QStringLiteral("speedFactor"), 1);
    PlcNetwork network = workspace.plcNetwork(PlcNetwork::M, 3);
    network.value = 99;
    workspace.plc().edit(Workspace::plcKey(PlcNetwork::M, 3), network);
    workspace.editDeadTimeMode(1, {DeadTimeMode::SeparateOnOff, 5, 1, 2});  // A's dead time kept
    workspace.analogueCams().edit(2, {2, {{30, 300}}});
    workspace.programmingProgram().edit({9, 0, 0});
    workspace.eepromLock().edit(false);
}

// The outputs 1..8 whose dead-time mode, or its dead time, is edited.
QList<int> changedModes(const Workspace& workspace) {
    QList<int> outputs;
    for (int output = 1; output <= 8; ++output)
        if (workspace.deadTimeModeChanged(output)) outputs << output;
    return outputs;
}

}  // namespace

class TestWorkspaceSections : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aReadMakesNoEdits() {
        Workspace workspace;
        QSignalSpy counts(&workspace, &Workspace::changedCountChanged);
        read(workspace, deviceA(), false);
        QCOMPARE(workspace.changedCount(), 0);
        QVERIFY(workspace.settings().known());
        editEach(workspace);
        QCOMPARE(workspace.changedCount(), 6);
        QCOMPARE(counts.last().at(0).toInt(), 6);
        // Device B read, edits kept: each stays an edit over B's values.
        read(workspace, deviceB(), true);
        QCOMPARE(workspace.changedCount(), 6);
        QCOMPARE(workspace.settings().deviceValue(QStringLiteral("speedFactor")),
                 std::optional<QVariant>(50000));
        QVERIFY(!workspace.settings().value(QStringLiteral("encoderText1")));  // not B's
        // Without keeping, B's values replace every edit.
        read(workspace, deviceB(), false);
        QCOMPARE(workspace.changedCount(), 0);
        QCOMPARE(counts.last().at(0).toInt(), 0);
    }

    void anotherDeviceKeepsWhatCarryOverSays_data() {
        QTest::addColumn<int>("carry");
        QTest::addColumn<int>("changedAfter");
        QTest::newRow("nothing") << int(CarryOver::Nothing) << 0;
        QTest::newRow("changes") << int(CarryOver::Changes) << 2;
        // Every item shown: 2 settings, 1 network, 2 modes, output 1's dead
        // time (word 0, in the cam section; output 2's is 0, which a device
        // without it holds too), 1 analogue output, the programming
        // program, the lock.
        QTest::newRow("everything") << int(CarryOver::Everything) << 9;
    }
    void anotherDeviceKeepsWhatCarryOverSays() {
        QFETCH(int, carry);
        QFETCH(int, changedAfter);
        Workspace workspace;
        read(workspace, deviceA(), false);
        workspace.setCopiesFrom(DeviceInfo{});
        workspace.settings().edit(QStringLiteral("speedFactor"), 1);
        workspace.editDeadTimeMode(2, {DeadTimeMode::Normal, 0, 0, 0});
        QSignalSpy modes(&workspace, &Workspace::deadTimeModesChanged);
        QSignalSpy tables(&workspace, &Workspace::tableSectionsChanged);
        workspace.forgetDeviceCopies(QStringLiteral("another device"), CarryOver(carry));
        QVERIFY(!modes.isEmpty());
        QVERIFY(!tables.isEmpty());
        QCOMPARE(workspace.changedCount(), changedAfter);
        QVERIFY(workspace.deadTimeModes().device().isEmpty());
        QVERIFY(!workspace.settings().known());
        QCOMPARE(workspace.carriedFrom().has_value(), CarryOver(carry) != CarryOver::Nothing);
        // Device B, read keeping what was carried: B lacks output 2, so
        // a carried edit of it has no row and goes.
        read(workspace, deviceB(), true);
        QVERIFY(!workspace.deadTimeModes().value(2));
        QCOMPARE(workspace.settings().value(QStringLiteral("speedFactor")),
                 std::optional<QVariant>(CarryOver(carry) == CarryOver::Nothing ? 50000 : 1));
    }

    void aProjectEditsOnlyTheOutputsTheDeviceHas() {
        Workspace workspace;
        const DeadTimeModes wanted{{1, {DeadTimeMode::Normal, 7, 0, 0}},
                                   {5, {DeadTimeMode::Normal, 8, 0, 0}}};
        // Before a read both wait as edits for the device's rows.
        workspace.mergeDeadTimeModes(wanted, ValueSource::File, false);
        QCOMPARE(changedModes(workspace), (QList<int>{1, 5}));
        workspace.mergeDeadTimeModes(deviceB().modes, ValueSource::Device, true);
        QCOMPARE(changedModes(workspace), QList<int>{1});
        QCOMPARE(workspace.deadTimeMode(1)->normal, 7);  // the project's, over B's 6
        // Once read, a project's output the device lacks is no edit.
        workspace.mergeDeadTimeModes(wanted, ValueSource::File, false);
        QCOMPARE(changedModes(workspace), QList<int>{1});
    }

    // Word 0 of a dead-time mode is the plain dead time of the Dead times
    // page (issue 38, item 3): one value, whichever page it is typed on,
    // read or written through.
    void theDeadTimeOfModeNormalHasOneHome() {
        Workspace workspace;
        read(workspace, deviceA(), false);
        CamDocument& cams = *workspace.cams();
        QCOMPARE(cams.deadTime(1), 5);  // read with the modes
        QCOMPARE(cams.deviceDeadTime(1), std::optional<qint32>(5));
        QSignalSpy modes(&workspace, &Workspace::deadTimeModesChanged);
        // Typed on the Dead times page: the modes page shows it, edited.
        cams.setDeadTime(1, 42);
        QVERIFY(!modes.isEmpty());
        QCOMPARE(workspace.deadTimeMode(1)->normal, 42);
        QCOMPARE(workspace.deviceDeadTimeMode(1)->normal, 5);
        QVERIFY(workspace.deadTimeModeChanged(1));
        QCOMPARE(workspace.changedCount(), 1);  // one item, not one on each page
        // Typed on the Dead-time modes page: the Dead times page shows it.
        workspace.editDeadTimeMode(1, {DeadTimeMode::Normal, 43, 0, 0});
        QCOMPARE(cams.deadTime(1), 43);
        QCOMPARE(workspace.changedCount(), 1);
        // A plain dead time written and read back: no edit on either page.
        cams.setDeviceDeadTime(1, 43);
        QVERIFY(!workspace.deadTimeModeChanged(1));
        QCOMPARE(workspace.changedCount(), 0);
        // A mode written and read back: the plain dead time's device copy too.
        workspace.editDeadTimeMode(2, {DeadTimeMode::Normal, 12, 0, 0});
        QCOMPARE(workspace.changedCount(), 2);  // its mode and its dead time
        workspace.setDeviceDeadTimeMode(2, {DeadTimeMode::Normal, 12, 0, 0});
        QCOMPARE(cams.deviceDeadTime(2), std::optional<qint32>(12));
        QCOMPARE(workspace.changedCount(), 0);
        // What a project saves is the one value.
        QCOMPARE(workspace.shownDeadTimeModes().value(2).normal, 12);
        QCOMPARE(cams.deadTimes().value(2), 12);
    }

    void aSectionTheProtocolLacksForgetsItsDeviceCopyOnly() {
        Workspace workspace;
        read(workspace, deviceA(), false);
        workspace.setReadTime(ProjectPart::PlcNetworks, QDateTime::currentDateTimeUtc());
        editEach(workspace);
        workspace.forgetDeviceSection(ProjectPart::PlcNetworks);
        QVERIFY(workspace.plc().device().isEmpty());
        QVERIFY(!workspace.readTimes().parts.contains(ProjectPart::PlcNetworks));
        QCOMPARE(workspace.changedCount(), 6);  // the edits stay
        workspace.forgetDeviceTableSections();
        QVERIFY(workspace.deadTimeModes().device().isEmpty());
        QVERIFY(!workspace.eepromLock().deviceValue());
        QCOMPARE(workspace.changedCount(), 6);
        QVERIFY(workspace.settings().known());
    }
};

QTEST_MAIN(TestWorkspaceSections)
#include "tst_workspace_sections.moc"
