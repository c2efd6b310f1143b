// Issue 6, points 6 and 7: the project file is the whole device, and the
// settings show exactly what the device holds.
#include "pty_simulator.h"

#include "model/camcon/project_file.h"
#include "ui/camcon/cam_page.h"
#include "ui/camcon/cameditor/cam_editor_widget.h"
#include "ui/camcon/cameditor/track_table_model.h"
#include "ui/camcon/device_writer.h"
#include "ui/camcon/setting_field.h"
#include "ui/camcon/settings_page.h"
#include "ui/language.h"
#include "ui/report_dialog.h"

#include <QComboBox>
#include <QLabel>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QWheelEvent>
#include <QtTest>

using namespace cambench;
using namespace cambench::test;

class WholeDeviceTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        useTestSettings();
        QVERIFY(setLanguage(QStringLiteral("en")));
    }
    void savedProjectAfterReadEverythingHoldsAllPrograms();
    void programNotReadShowsNotRead();
    void saveRightAfterStartWorksOnTheDemoDevice();
    void saveWhileLoadingIsRefused();
    void writingAProgramNeverReadWritesItWhole();
    void deviceValueOutsideTheRangeIsShownAsItIs();
    void wheelOverAnUnfocusedFieldDoesNotChangeIt();
};

void WholeDeviceTest::savedProjectAfterReadEverythingHoldsAllPrograms() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QSignalSpy done(camConWindow(shell->window()), &CamConWindow::everythingRead);
    camConWindow(shell->window())->readEverything(0);
    QVERIFY(done.wait(kDeviceTimeoutMs));
    QVERIFY(done.first().first().toBool());
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("device.json"));
    QVERIFY(camConWindow(shell->window())->saveProjectTo(path).ok());
    const Result<Project> saved = loadProject(path);
    QVERIFY2(saved.ok(), qPrintable(saved.error().message));
    const int programs = camConWorkspace(*shell)->info().programs;
    QCOMPARE(saved->programs.size(), programs);
    QCOMPARE(saved->readAt.programs.size(), programs);  // each read, with its time
    // The demo device's programs 1 and 2 hold cams.
    for (int number : {1, 2}) {
        const auto program =
            std::find_if(saved->programs.cbegin(), saved->programs.cend(),
                         [number](const CamProgram& p) { return p.number == number; });
        QVERIFY(program != saved->programs.cend());
        QVERIFY(!program->tracks.isEmpty());
    }
    for (ProjectPart part : {ProjectPart::Device, ProjectPart::Settings, ProjectPart::DeadTimes,
                             ProjectPart::Users, ProjectPart::PlcNetworks})
        QVERIFY2(saved->readAt.parts.contains(part), qPrintable(QString::number(int(part))));
    QVERIFY(!saved->users.isEmpty());
    QVERIFY(!saved->plcNetworks.isEmpty());
}

void WholeDeviceTest::programNotReadShowsNotRead() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    CamEditorWidget* editor = camConWindow(shell->window())->camPage()->editor();
    CamDocument* cams = camConWorkspace(*shell)->cams();
    QVERIFY(!cams->hasDeviceCopy(1));
    QCOMPARE(cams->trackState(1, 1), ChangeState::NotRead);
    editor->setCurrentProgram(1);
    const QModelIndex state = editor->trackModel()->index(0, TrackTableModel::StateColumn);
    QCOMPARE(state.data().toString(), QStringLiteral("not read"));
    auto* chooser = editor->findChild<QComboBox*>();
    QVERIFY(chooser);
    QVERIFY2(chooser->itemText(1).contains(QStringLiteral("not read")),
             qPrintable(chooser->itemText(1)));
    QVERIFY(!chooser->itemText(0).contains(QStringLiteral("not read")));
}

void WholeDeviceTest::saveRightAfterStartWorksOnTheDemoDevice() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QVERIFY(waitForSections(*shell));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("start.json"));
    // The demo device holds settings outside the manual's ranges: saved as they are.
    const Status saved = camConWindow(shell->window())->saveProjectTo(path);
    QVERIFY2(saved.ok(), qPrintable(saved.ok() ? QString() : saved.error().message));
    const Result<Project> loaded = loadProject(path);
    QVERIFY2(loaded.ok(), qPrintable(loaded.error().message));
    QVERIFY(!validateProject(*loaded).isEmpty());  // warned about, not refused
    QCOMPARE(loaded->settings, camConWorkspace(*shell)->settings().device());
    QVERIFY(!loaded->users.isEmpty());
    QVERIFY(shell->window()->lastMessage().contains(QStringLiteral("outside")));
}

void WholeDeviceTest::saveWhileLoadingIsRefused() {
    auto shell = std::make_unique<Shell>();
    shell->start(QStringLiteral("sim:throttle=0"));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("half.json"));
    // Answer the refusal's message so the test goes on.
    NextDialog<ReportDialog> close([](ReportDialog* dialog) { dialog->accept(); });
    QTRY_VERIFY_WITH_TIMEOUT(camConWindow(shell->window())->isReadingDevice(), kDeviceTimeoutMs);
    QVERIFY(!camConWindow(shell->window())->saveProjectTo(path).ok());
    QVERIFY(!QFile::exists(path));
    QCOMPARE(close.answered(), 1);
    QTRY_VERIFY_WITH_TIMEOUT(!camConWindow(shell->window())->isReadingDevice(), kDeviceTimeoutMs);
    QVERIFY(camConWindow(shell->window())->saveProjectTo(path).ok());
}

void WholeDeviceTest::writingAProgramNeverReadWritesItWhole() {
    PtySimulator sim;
    auto shell = startOnPty(sim);
    QVERIFY(shell);
    CamDocument* cams = camConWorkspace(*shell)->cams();
    QVERIFY(!cams->hasDeviceCopy(3));
    cams->insertCam(3, 4, {10, 20});
    std::optional<WriteResult> result;
    camConWindow(shell->window())->camPage()->writeProgram(3, [&](const WriteResult& r) {
        result = r;
    });
    QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), kDeviceTimeoutMs);
    QVERIFY2(result->ok(), qPrintable(writeSummary(*result)));
    const usecases::WriteReport& report = result->value();
    // Every output of the program was looked at; the counts add up to them.
    QCOMPARE(report.tracks.size(), camConWorkspace(*shell)->info().outputs);
    QCOMPARE(
        report.count(usecases::WriteState::Written) + report.count(usecases::WriteState::Unchanged),
        report.total());
    QCOMPARE(sim.track(3, 4), (QList<Cam>{{10, 20}}));
    // The program is known now: what is on the device is what is shown.
    QVERIFY(cams->hasDeviceCopy(3));
    QCOMPARE(cams->trackState(3, 4), ChangeState::Unchanged);
}

void WholeDeviceTest::deviceValueOutsideTheRangeIsShownAsItIs() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QVERIFY(waitForSections(*shell));
    Workspace* ws = camConWorkspace(*shell);
    // A value the device holds below the manual's minimum.
    QString key;
    for (const SettingSpec& spec : settingSpecs()) {
        const QString candidate = QString::fromLatin1(spec.key);
        if ((spec.kind == SettingKind::Integer || spec.kind == SettingKind::Fixed) &&
            !spec.readOnly &&
            ws->settings().deviceValue(candidate).value_or(spec.min).toLongLong() < spec.min) {
            key = candidate;
            break;
        }
    }
    QVERIFY2(!key.isEmpty(), "the demo device holds a setting below its minimum");
    SettingField* field = camConWindow(shell->window())->settingsPage()->field(key);
    QCOMPARE(field->value(), ws->settings().deviceValue(key).value_or(QVariant()));  // not clamped
    QVERIFY(!field->problem().isEmpty());                                            // flagged
    QVERIFY(field->label()->text().contains(QStringLiteral("⚠")));
    QVERIFY(!field->isMarkedChanged());  // not an edit
    QVERIFY(!field->label()->text().startsWith(QStringLiteral("● ")));
    QVERIFY(!ws->settings().isChanged(key));
    QCOMPARE(ws->changedCount(), 0);
    QVERIFY(field->editor()->toolTip().contains(QStringLiteral("outside")));
}

void WholeDeviceTest::wheelOverAnUnfocusedFieldDoesNotChangeIt() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QVERIFY(waitForSections(*shell));
    MainWindow* window = shell->window();
    camConWindow(window)->showSection(CamConWindow::Settings);
    SettingField* field = nullptr;
    for (const SettingSpec& spec : settingSpecs()) {
        if (spec.kind == SettingKind::Integer && !spec.readOnly) {
            field = camConWindow(window)->settingsPage()->field(QString::fromLatin1(spec.key));
            if (qobject_cast<QSpinBox*>(field->editor())) break;
        }
    }
    auto* spin = qobject_cast<QSpinBox*>(field->editor());
    QVERIFY(spin);
    camConWindow(window)->settingsPage()->showSetting(QString::fromLatin1(field->spec().key));
    spin->clearFocus();
    const int before = spin->value();
    const QPoint centre = spin->rect().center();
    QWheelEvent wheel(centre, spin->mapToGlobal(centre), QPoint(), QPoint(0, 120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(spin, &wheel);
    QCOMPARE(spin->value(), before);
    QCOMPARE(camConWorkspace(*shell)->changedCount(), 0);
}

QTEST_MAIN(WholeDeviceTest)
#include "tst_whole_device.moc"
