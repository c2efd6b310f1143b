// The CamCon's pages and models: generated settings form, masked user
// numbers, PLC symbols, language switch, report, project, and every model
// under QAbstractItemModelTester.
#include "camcon_fixture.h"

#include "ui/camcon/access_grid_model.h"
#include "ui/camcon/commissioning_report.h"
#include "ui/camcon/dead_times_model.h"
#include "ui/camcon/dead_times_page.h"
#include "ui/camcon/incoming_values.h"
#include "ui/camcon/plc_matrix_model.h"
#include "ui/camcon/plc_page.h"
#include "ui/camcon/plc_symbol.h"
#include "ui/camcon/project_io.h"
#include "ui/camcon/setting_field.h"
#include "ui/camcon/settings_page.h"
#include "ui/camcon/users_model.h"
#include "ui/camcon/users_page.h"
#include "ui/device_session.h"
#include "ui/language.h"

#include <QAbstractItemModelTester>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTextDocument>
#include <QTranslator>
#include <QtTest>

using namespace cambench;
using namespace cambench::test;

class CamConPagesTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    // As the application does at start: English catalogue (plural forms).
    void initTestCase() {
        useTestSettings();
        QVERIFY(setLanguage(QStringLiteral("en")));
    }
    void modelsPassTheModelTester();
    void settingsFormShowsRangeAndTooltipOfSpec();
    void settingsEditMarksFieldUntilWritten();
    void userNumbersMaskedUntilRevealed();
    void plcSymbolsDecodeWhereKnownAndStayEditableAsHex();
    void plcMatrixEditMarksNetworkChanged();
    void languageSwitchShowsGermanLabels();
    void everySettingTextHasAGermanTranslation();
    void reportPdfHoldsIdentityAndPrograms();
    void projectRoundTripKeepsEditsAsUnwritten();
};

void CamConPagesTest::modelsPassTheModelTester() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QVERIFY(waitForSections(*shell));
    Workspace* ws = camConWorkspace(*shell);
    DeadTimesModel deadTimes(ws);
    UsersModel users(ws);
    AccessGridModel access(ws);
    PlcMatrixModel plc(ws);
    QAbstractItemModelTester t1(&deadTimes, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QAbstractItemModelTester t2(&users, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QAbstractItemModelTester t3(&access, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QAbstractItemModelTester t4(&plc, QAbstractItemModelTester::FailureReportingMode::QtTest);
    // Changes while the testers watch: capacities, users, access, symbols.
    DeviceInfo info = ws->info();
    info.outputs = 48;
    info.deadTimeOutputs = 48;
    ws->setInfo(info, true);
    QCOMPARE(deadTimes.rowCount(), 48);
    access.setUser(0);
    QCOMPARE(access.rowCount(), 6);
    QVERIFY(access.setData(access.index(0, 3), Qt::Checked, Qt::CheckStateRole) ||
            ws->users().row(0).user.allOutputs);
    User user;
    user.name = QStringLiteral("Night shift");
    user.number = QStringLiteral("4711");
    ws->users().add(user);
    QCOMPARE(users.rowCount(), int(ws->users().size()));
    ws->users().remove(int(ws->users().size()) - 1);
    plc.setNetwork(PlcNetwork::M, 4);
    QVERIFY(plc.setData(plc.index(1, 2), QStringLiteral("M11")));
    QVERIFY(!plc.setData(plc.index(1, 2), QStringLiteral("not a symbol")));
}

void CamConPagesTest::settingsFormShowsRangeAndTooltipOfSpec() {
    Workspace workspace;
    DeviceSession session;
    SettingsPage page(&session, &workspace);
    const SettingSpec* integer = nullptr;
    for (const SettingSpec& spec : settingSpecs()) {
        if (spec.kind == SettingKind::Integer && !spec.readOnly && *spec.tooltip &&
            spec.min >= std::numeric_limits<int>::min() &&
            spec.max <= std::numeric_limits<int>::max()) {
            integer = &spec;
            break;
        }
    }
    QVERIFY(integer);
    SettingField* field = page.field(QString::fromLatin1(integer->key));
    QVERIFY(field);
    auto* spin = qobject_cast<QSpinBox*>(field->editor());
    QVERIFY(spin);
    QCOMPARE(spin->minimum(), int(integer->min));
    QCOMPARE(spin->maximum(), int(integer->max));
    QVERIFY(field->editor()->toolTip().contains(QString::fromUtf8(integer->tooltip)));
    QVERIFY(field->editor()->toolTip().contains(QString::number(integer->max)));
    QVERIFY(field->rangeLabel()->text().contains(QString::number(integer->max)));

    // Output references show "none" for 0.
    for (const SettingSpec& spec : settingSpecs()) {
        if (spec.kind != SettingKind::OutputRef) continue;
        auto* ref = qobject_cast<QSpinBox*>(page.field(QString::fromLatin1(spec.key))->editor());
        QVERIFY(ref);
        QCOMPARE(ref->minimum(), 0);
        QCOMPARE(ref->specialValueText(), QStringLiteral("none"));
        break;
    }
}

void CamConPagesTest::settingsEditMarksFieldUntilWritten() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QVERIFY(waitForSections(*shell));
    Workspace* ws = camConWorkspace(*shell);
    SettingsPage* page = camConWindow(shell->window())->settingsPage();
    const SettingSpec* spec = nullptr;
    for (const SettingSpec& s : settingSpecs()) {
        if (s.kind == SettingKind::Integer && !s.readOnly &&
            ws->settings().deviceValue(QString::fromLatin1(s.key)).value_or(s.max).toLongLong() <
                s.max) {
            spec = &s;
            break;
        }
    }
    QVERIFY(spec);
    const QString key = QString::fromLatin1(spec->key);
    SettingField* field = page->field(key);
    auto* spin = qobject_cast<QSpinBox*>(field->editor());
    QVERIFY(spin);
    spin->setValue(spin->value() + 1);
    QCOMPARE(ws->settings().changedKeys(), QStringList{key});
    QVERIFY(field->label()->text().startsWith(QStringLiteral("● ")));

    std::optional<WriteResult> result;
    page->writeChanges([&](const WriteResult& r) { result = r; });
    QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), kDeviceTimeoutMs);
    QVERIFY2(result->ok() && result->value().complete(), qPrintable(writeSummary(*result)));
    QCOMPARE(result->value().count(usecases::WriteState::Written), 1);
    QVERIFY(ws->settings().changedKeys().isEmpty());
    QVERIFY(!field->label()->text().startsWith(QStringLiteral("● ")));
}

void CamConPagesTest::userNumbersMaskedUntilRevealed() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QVERIFY(waitForSections(*shell));
    UsersPage* page = camConWindow(shell->window())->usersPage();
    const QString number = camConWorkspace(*shell)->users().row(0).user.number;
    QVERIFY(!number.isEmpty());
    const QModelIndex cell = page->model()->index(0, UsersModel::NumberColumn);
    page->selectUser(0);
    QCOMPARE(cell.data().toString(), QStringLiteral("*****"));
    QVERIFY(page->numberEdit()->text().isEmpty());
    QVERIFY(page->numberEdit()->isReadOnly());
    for (const SectionDifference& d : page->differences()) QVERIFY(!d.device.contains(number));

    page->setNumbersShown(true);
    QCOMPARE(cell.data().toString(), number);
    QCOMPARE(page->numberEdit()->text(), number);
    QVERIFY(!page->numberEdit()->isReadOnly());
    page->setNumbersShown(false);
    QCOMPARE(cell.data().toString(), QStringLiteral("*****"));
}

void CamConPagesTest::plcSymbolsDecodeWhereKnownAndStayEditableAsHex() {
    QCOMPARE(plcsymbol::display(0), QString());
    QCOMPARE(plcsymbol::display(0x0A0A), QStringLiteral("M 11"));
    QCOMPARE(plcsymbol::display(0x0101), QStringLiteral("0x0101"));
    QCOMPARE(plcsymbol::parse(QStringLiteral("M11")), std::optional<quint16>(0x0A0A));
    QCOMPARE(plcsymbol::parse(QStringLiteral("0101")), std::optional<quint16>(0x0101));
    QCOMPARE(plcsymbol::parse(QStringLiteral("0x1F2e")), std::optional<quint16>(0x1F2E));
    QCOMPARE(plcsymbol::parse(QString()), std::optional<quint16>(0));
    QVERIFY(!plcsymbol::parse(QStringLiteral("M0")));
    QVERIFY(!plcsymbol::parse(QStringLiteral("12345")));
    QCOMPARE(plcsymbol::editText(0x0A0A), QStringLiteral("0A0A"));
}

void CamConPagesTest::plcMatrixEditMarksNetworkChanged() {
    Workspace workspace;
    PlcNetwork network;
    network.area = PlcNetwork::X;
    network.number = 2;
    network.symbols[0] = 0x0A00;
    workspace.plc().merge(Workspace::plcByKey({network}), ValueSource::Device, false);
    PlcMatrixModel model(&workspace);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    model.setNetwork(PlcNetwork::X, 2);
    QCOMPARE(model.index(0, 0).data().toString(), QStringLiteral("M 1"));
    QVERIFY(model.setData(model.index(4, 5), QStringLiteral("ABCD")));
    QCOMPARE(workspace.plcNetwork(PlcNetwork::X, 2).symbols[29], quint16(0xABCD));
    QVERIFY(model.index(4, 5).data().toString().startsWith(QStringLiteral("● ")));
    QCOMPARE(workspace.plc().changedKeys(), QList<int>{Workspace::plcKey(PlcNetwork::X, 2)});
}

void CamConPagesTest::languageSwitchShowsGermanLabels() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    CamDocument* cams = camConWorkspace(*shell)->cams();
    Cam cam = cams->track(0, 1).cams.first();
    cam.on += 1;
    cams->setCam(0, 1, 0, cam);
    QSignalSpy rebuilt(shell.get(), &Shell::windowRebuilt);
    shell->switchLanguage(QStringLiteral("de"));
    QCOMPARE(rebuilt.size(), 1);
    auto* nav = shell->window()->findChild<QListWidget*>();
    QVERIFY(nav);
    QCOMPARE(nav->item(MainWindow::Connection)->text(), QStringLiteral("Verbindung"));
    const SectionPage* deadTimes =
        camConWindow(shell->window())->sectionPage(CamConWindow::DeadTimes);
    QCOMPARE(nav->item(shell->window()->rowOf(deadTimes))->text(), QStringLiteral("Totzeiten"));
    // A section the protocol lacks is greyed in the rebuilt window too.
    auto* modes = qobject_cast<CapabilityGate*>(
        camConWindow(shell->window())->sectionPage(CamConWindow::DeadTimeModes));
    QVERIFY(modes);
    QTRY_VERIFY_WITH_TIMEOUT(!modes->isAvailable(), kDeviceTimeoutMs);
    // The edit and the line survived the rebuilt window.
    QCOMPARE(cams->track(0, 1).cams.first(), cam);
    QVERIFY(shell->session()->isOnline());
    shell->switchLanguage(QStringLiteral("en"));
    nav = shell->window()->findChild<QListWidget*>();
    QCOMPARE(nav->item(MainWindow::Connection)->text(), QStringLiteral("Connection"));
}

void CamConPagesTest::everySettingTextHasAGermanTranslation() {
    QTranslator german;
    QVERIFY(german.load(QStringLiteral(":/i18n/cambench_de.qm")));
    QStringList missing;
    const auto check = [&](const char* text) {
        if (!text || !*text) return;
        if (german.translate("Settings", text).isEmpty()) missing << QString::fromUtf8(text);
    };
    for (const SettingSpec& spec : settingSpecs()) {
        check(spec.label);
        check(spec.tooltip);
        for (const SettingChoice& choice : spec.choices) check(choice.label);
    }
    QVERIFY2(missing.isEmpty(),
             qPrintable(QStringLiteral("untranslated (run the update_setting_texts "
                                       "target and lupdate): ") +
                        missing.join(QStringLiteral(" | "))));
}

void CamConPagesTest::reportPdfHoldsIdentityAndPrograms() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QTextDocument document;
    CommissioningReport::build(document, *camConWorkspace(*shell));
    const QString text = document.toPlainText();
    QVERIFY(text.contains(QStringLiteral("11.10.1994")));
    QVERIFY(text.contains(QStringLiteral("Program 0")));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("report.pdf"));
    QVERIFY(CommissioningReport::write(path, *camConWorkspace(*shell)).ok());
    QFile pdf(path);
    QVERIFY(pdf.open(QIODevice::ReadOnly));
    QVERIFY(pdf.read(5) == "%PDF-");
}

void CamConPagesTest::projectRoundTripKeepsEditsAsUnwritten() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QVERIFY(waitForSections(*shell));
    const Project saved = projectFromWorkspace(*camConWorkspace(*shell));
    QVERIFY(!saved.programs.isEmpty());
    Workspace offline;
    offline.setInfo(saved.device, false);
    mergeIncoming(offline, saved, ValueSource::File, {});
    QCOMPARE(offline.cams()->program(0).tracks, camConWorkspace(*shell)->cams()->program(0).tracks);
    QCOMPARE(offline.settings().shown(), camConWorkspace(*shell)->settings().shown());
    // Nothing of a loaded project is on a device yet.
    QVERIFY(offline.changedCount() > 0);
    // The same values; no read times: nothing of it was read from a device here.
    Project expected = saved;
    expected.readAt = {};
    QCOMPARE(projectToJson(projectFromWorkspace(offline)), projectToJson(expected));
}

QTEST_MAIN(CamConPagesTest)
#include "tst_camcon_pages.moc"
