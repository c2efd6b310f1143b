// The CamCon workspace in model/ (issue 38, item 3), linked without any
// widget: its sections, totals and device changes work on their own, and
// the cam section attached to it (the GUI's cam document) is told of every
// limit, clear and device change and counted in the totals.
#include "model/camcon/device_workspace.h"

#include <QSignalSpy>
#include <QtTest>

using namespace cambench;

namespace {

// Records what the workspace asks of its cam section.
class RecordingCams : public CamSection {
public:
    void setLimits(const DeviceInfo& info, bool rotary) override {
        limits = info;
        m_rotary = rotary;
    }
    bool isRotary() const override { return m_rotary; }
    void clear() override { ++clears; }
    void forgetDeviceCopies(CarryOver carry) override { forgotten << carry; }
    int changedCount() const override { return changed; }
    const Names& names() const override { return m_names; }
    const DeadTimes& deadTimes() const override { return m_deadTimes; }
    bool outputSettingsKnown() const override { return false; }
    std::optional<qint32> deviceDeadTime(int) const override { return std::nullopt; }
    std::optional<QString> deviceOutputName(int) const override { return std::nullopt; }
    int outputSettingsEditCount() const override { return 0; }
    void mergeOutputSettings(const QMap<int, QString>&, const DeadTimes& deadTimes, bool,
                             bool) override {
        m_deadTimes = deadTimes;
    }
    void mergeDeadTime(int output, qint32 deadTime, bool, bool) override {
        m_deadTimes.insert(output, deadTime);
    }
    void setDeviceDeadTime(int, qint32) override {}
    void setDeadTime(int output, qint32 deadTime) override { m_deadTimes.insert(output, deadTime); }

    DeviceInfo limits;
    int clears = 0;
    QList<CarryOver> forgotten;
    int changed = 0;

private:
    bool m_rotary = false;
    Names m_names;
    DeadTimes m_deadTimes;
};

class WorkspaceWithCams : public DeviceWorkspace {
public:
    explicit WorkspaceWithCams(RecordingCams* cams) { attachCams(cams); }
    void camsChanged() { notifyChanged(); }
};

DeviceInfo device(int outputs) {
    DeviceInfo info;
    info.outputs = outputs;
    info.deadTimeOutputs = outputs;
    return info;
}

}  // namespace

class TestDeviceWorkspace : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void worksWithoutCams() {
        DeviceWorkspace workspace;
        QSignalSpy counts(&workspace, &DeviceWorkspace::changedCountChanged);
        workspace.settings().mergeWhole({{QStringLiteral("speedFactor"), 100000}}, false);
        workspace.settings().edit(QStringLiteral("speedFactor"), 1);
        QCOMPARE(workspace.changedCount(), 1);
        QCOMPARE(counts.size(), 1);
        QVERIFY(!workspace.outputSettingsKnown());
        QCOMPARE(workspace.outputSettingsEditCount(), 0);
        workspace.forgetDeviceCopies(QStringLiteral("another device"), CarryOver::Changes);
        QCOMPARE(workspace.changedCount(), 1);  // the edit stays
        workspace.clear(device(16));
        QCOMPARE(workspace.changedCount(), 0);
    }

    void tellsItsCamSection() {
        RecordingCams recording;
        RecordingCams* cams = &recording;
        WorkspaceWithCams workspace(cams);
        workspace.setInfo(device(16), true);
        QCOMPARE(cams->limits.outputs, 16);
        QVERIFY(cams->isRotary());  // no axis type: rotary
        // A linear axis in the settings: the cams follow.
        workspace.settings().edit(QStringLiteral("axisType"), 1);
        QVERIFY(!cams->isRotary());
        workspace.forgetDeviceCopies(QStringLiteral("another device"), CarryOver::Everything);
        QCOMPARE(cams->forgotten, QList<CarryOver>{CarryOver::Everything});
        workspace.clear(device(32));
        QCOMPARE(cams->clears, 1);
        QCOMPARE(cams->limits.outputs, 32);
        // The cams' changes count in the totals, and say so.
        QSignalSpy counts(&workspace, &DeviceWorkspace::changedCountChanged);
        cams->changed = 3;
        workspace.camsChanged();
        QCOMPARE(workspace.changedCount(), 3);
        QCOMPARE(counts.size(), 1);
        // A file's dead times leave the outputs it does not name as they are.
        workspace.mergeOutputSettings({}, {{2, 20}}, ValueSource::File, false);
        workspace.mergeOutputSettings({}, {{5, 50}}, ValueSource::File, false);
        QCOMPARE(cams->deadTimes(), (DeadTimes{{2, 20}, {5, 50}}));
    }
};

QTEST_MAIN(TestDeviceWorkspace)
#include "tst_device_workspace.moc"
