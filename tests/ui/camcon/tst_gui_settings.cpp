// Issue 9, item 3: what the GUI remembers survives a restart, shown on a
// CamCon: the last connection (port, Multiuser protocol and its device and
// PC numbers), the window, its section, the language, the palette and the
// recent projects, with the CamCon's File → Recent files menu. Settings live
// in a temporary directory for the test.
#include "camcon_fixture.h"

#include "ui/connection_page.h"
#include "ui/device_session.h"
#include "ui/gui_settings.h"
#include "ui/language.h"
#include "ui/report_dialog.h"
#include "ui/theme.h"

#include "comm/camcon/ascii/ascii_protocol.h"

#include <QMenu>
#include <QTemporaryDir>
#include <QtTest>

using namespace cambench;
using namespace cambench::test;

class GuiSettingsTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        QVERIFY(m_settings.isValid());
        QCoreApplication::setOrganizationName(QStringLiteral("CamBench"));
        QCoreApplication::setApplicationName(QStringLiteral("CamBench-settings-test"));
        QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, m_settings.path());
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settings.path());
        QSettings().clear();
        QVERIFY(setLanguage(QStringLiteral("en")));
    }
    void everythingRememberedSurvivesARestart();
    void recentFilesMenuOpensAndForgetsMissingFiles();

private:
    QTemporaryDir m_settings;
};

void GuiSettingsTest::everythingRememberedSurvivesARestart() {
    QTemporaryDir dir;
    const QString project = dir.filePath(QStringLiteral("press-3.json"));
    const QString port = QStringLiteral("sim:throttle=0;devices=4;framing=multiuser");
    QRect geometry;
    {
        // First run: connect over Multiuser to device 4, work, switch language and palette.
        Shell first;
        first.start({});
        ConnectionPage* page = first.window()->connectionPage();
        page->setPort(port);
        page->setProtocol(QStringLiteral("multiuser"));
        comm::AsciiProtocolSettings multiuser(comm::Framing::Multiuser);
        QVariantMap map = multiuser.toMap();
        map.insert(QStringLiteral("device"), 4);
        map.insert(QStringLiteral("pcNumber"), 12);
        multiuser.fromMap(map);
        comm::ConnectionSettings connection = page->connectionSettings();
        first.session()->connectTo(connection,
                                   std::make_shared<comm::AsciiProtocolSettings>(multiuser));
        QTRY_VERIFY_WITH_TIMEOUT(first.session()->isOnline(), kDeviceTimeoutMs);
        // Another device than the demo: it is identified and read first.
        QTRY_VERIFY_WITH_TIMEOUT(
            first.session()->deviceChecked() && !camConWindow(first.window())->isReadingDevice(),
            kDeviceTimeoutMs);
        QVERIFY(camConWindow(first.window())->saveProjectTo(project).ok());
        first.window()->resize(1100, 700);
        first.window()->move(30, 40);
        camConWindow(first.window())->showSection(CamConWindow::Monitor);
        first.switchLanguage(QStringLiteral("de"));
        guisettings::setDark(true);
        geometry = first.window()->geometry();
        QVERIFY(first.window()->close());
    }
    QSettings().sync();
    setLanguage(QStringLiteral("en"));

    // What the next start of cambench reads (main.cpp).
    QCOMPARE(guisettings::language(), QStringLiteral("de"));
    QCOMPARE(guisettings::dark(), std::optional<bool>(true));
    const auto remembered = guisettings::loadConnection();
    QVERIFY(remembered.has_value());
    QCOMPARE(remembered->connection.port, port);
    QCOMPARE(remembered->protocol->protocolId(), QStringLiteral("multiuser"));
    QCOMPARE(remembered->protocol->toMap().value(QStringLiteral("device")).toInt(), 4);
    QCOMPARE(remembered->protocol->toMap().value(QStringLiteral("pcNumber")).toInt(), 12);
    QCOMPARE(guisettings::recentProjects().value(0), QFileInfo(project).absoluteFilePath());

    // Second run without a port: the remembered line, window and section.
    Shell second;
    second.start({});
    QTRY_VERIFY_WITH_TIMEOUT(second.session()->isOnline(), kDeviceTimeoutMs);
    QCOMPARE(second.session()->connection().port, port);
    QCOMPARE(second.session()->protocol().protocolId(), QStringLiteral("multiuser"));
    QCOMPARE(second.session()->protocol().device(), 4);
    QCOMPARE(second.window()->connectionPage()->protocolSettings()->device(), 4);
    QCOMPARE(
        second.window()->currentSection(),
        second.window()->rowOf(camConWindow(second.window())->sectionPage(CamConWindow::Monitor)));
    QCOMPARE(second.window()->size(), geometry.size());
    QSignalSpy done(second.window(), &MainWindow::loaded);
    QVERIFY(done.wait(kDeviceTimeoutMs));
    QVERIFY(done.first().first().toBool());
    QCOMPARE(camConWorkspace(second)->info().deviceNumber, 4);
}

void GuiSettingsTest::recentFilesMenuOpensAndForgetsMissingFiles() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QTemporaryDir dir;
    const QString kept = dir.filePath(QStringLiteral("kept.json"));
    const QString gone = dir.filePath(QStringLiteral("gone.json"));
    QVERIFY(camConWindow(shell->window())->saveProjectTo(gone).ok());
    QVERIFY(camConWindow(shell->window())->saveProjectTo(kept).ok());
    QFile::remove(gone);
    QMenu* recent = camConWindow(shell->window())->recentFilesMenu();
    Q_EMIT recent->aboutToShow();
    QStringList texts;
    for (QAction* action : recent->actions()) texts << action->text();
    QVERIFY2(texts.value(0) == QStringLiteral("&1 kept.json") &&
                 texts.value(1) == QStringLiteral("&2 gone.json"),
             qPrintable(texts.join(QLatin1Char('|'))));
    // A file that is gone says so and leaves the list.
    NextDialog<ReportDialog> close([](ReportDialog* dialog) { dialog->accept(); });
    recent->actions().at(1)->trigger();
    QCOMPARE(close.answered(), 1);
    QVERIFY(!guisettings::recentProjects().contains(QFileInfo(gone).absoluteFilePath()));
    recent->actions().at(0)->trigger();
    QCOMPARE(camConWorkspace(*shell)->projectPath(), QFileInfo(kept).absoluteFilePath());
}

QTEST_MAIN(GuiSettingsTest)
#include "tst_gui_settings.moc"
