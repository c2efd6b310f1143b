// Issue 13, point 6: a device family that exists only in this test -
// protocol, device interface, simulator, one page, one CLI command (see
// fake_family.h) - registered from here alone, is hosted by the shell: the
// GUI connects to it on the in-process simulator, shows its page and hides
// the CamCon's, and cambench-cli's front runs its command.
#include "fake_family.h"

#include "app/cli/command_line.h"
#include "app/registry/family_parts.h"
#include "comm/device/family_registry.h"
#include "ui/connection_page.h"
#include "ui/connection_status.h"
#include "ui/device_session.h"
#include "ui/main_window.h"
#include "ui/screenshot_tour.h"
#include "ui/shell.h"

#include <QAction>
#include <QComboBox>
#include <QCoreApplication>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardItemModel>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace cambench;

namespace {

constexpr int kTimeoutMs = 60000;  // bounds a wait; never a pass/fail threshold

QListWidgetItem* navItem(MainWindow* window, const QString& title) {
    auto* nav = window->findChild<QListWidget*>();
    const QList<QListWidgetItem*> items = nav->findItems(title, Qt::MatchExactly);
    return items.isEmpty() ? nullptr : items.first();
}

QAction* menuEntry(MainWindow* window, const QString& text) {
    for (QAction* action : window->findChildren<QAction*>())
        if (action->text() == text) return action;
    return nullptr;
}

bool connectVia(Shell& shell, const QString& protocol) {
    ConnectionPage* page = shell.window()->connectionPage();
    page->setPort(QStringLiteral("sim:throttle=0"));
    page->setProtocol(protocol);
    QSignalSpy loaded(shell.window(), &MainWindow::loaded);
    shell.window()->connectAndLoad();
    return loaded.wait(kTimeoutMs) && loaded.first().first().toBool();
}

}  // namespace

class TestFakeFamily : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CamBench"));
        QCoreApplication::setApplicationName(QStringLiteral("CamBench-tests"));
        QStandardPaths::setTestModeEnabled(true);
        // Its own settings file: tests running beside it (ctest -j2) keep theirs.
        QVERIFY(m_settings.isValid());
        QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, m_settings.path());
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settings.path());
        QSettings().clear();
        fake::registerFakeFamily();
        // A family known by name whose code is not built yet.
        comm::FamilyRegistry::instance().add(
            comm::FamilyInfo::announced(QStringLiteral("coming"), QStringLiteral("Coming Drive"),
                                        QStringLiteral("coming-line")));
    }

    // Registered through its FamilyParts as a built-in family is, it has
    // every part the GUI and the CLI must have (this test links both).
    void theFamilyIsComplete() {
        const QString fake = QStringLiteral("family \"fake\"");
        QCOMPARE(missingFamilyParts(Program::Gui).filter(fake), QStringList());
        QCOMPARE(missingFamilyParts(Program::Cli).filter(fake), QStringList());
    }

    // Adding this family touched one file outside its folder, tests/family/:
    // tests/CMakeLists.txt, whose one line includes family/tests.cmake. Its
    // registration place is its own (fakeParts, registered by the test).
    // The shell's GUI tests (tests/ui/shell/) use it as their family: they
    // are its users, not places its adding touched.
    void addingItTouchedOneFileOutsideItsFolder() {
        const QString root = QStringLiteral(CAMBENCH_SOURCE_DIR);
        // What using the family takes: its header, its parts, its list.
        const QStringList names{QStringLiteral("fake_family.h"), QStringLiteral("fakeParts"),
                                QStringLiteral("registerFakeFamily"),
                                QStringLiteral("family/tests.cmake")};
        QStringList touched;
        QDirIterator it(root,
                        {QStringLiteral("*.cpp"), QStringLiteral("*.h"), QStringLiteral("*.cmake"),
                         QStringLiteral("CMakeLists.txt")},
                        QDir::Files, QDirIterator::Subdirectories);
        while (it.hasNext()) {
            const QString path = QDir(root).relativeFilePath(it.next());
            if (path.startsWith(QLatin1String("tests/family/")) ||
                path.startsWith(QLatin1String("tests/ui/shell/")) ||
                path.startsWith(QLatin1String("build")) || path.startsWith(QLatin1Char('.')))
                continue;
            QFile file(it.filePath());
            if (!file.open(QIODevice::ReadOnly)) continue;
            const QString text = QString::fromUtf8(file.readAll());
            for (const QString& name : names) {
                if (text.contains(name)) {
                    touched << path;
                    break;
                }
            }
        }
        QCOMPARE(touched, QStringList{QStringLiteral("tests/CMakeLists.txt")});
    }

    // An announced family is shown greyed with the reason, never hidden, and
    // asking for it gets that answer, not "unknown".
    void anAnnouncedFamilyIsShownAndRefusedByName() {
        const Result<const comm::FamilyInfo*> usable =
            comm::FamilyRegistry::instance().usable(QStringLiteral("coming"));
        QVERIFY(!usable.ok());
        QVERIFY2(usable.error().message.contains(QLatin1String("not built into this CamBench yet")),
                 qPrintable(usable.error().message));
        QCOMPARE(cli::runCommandLine({QStringLiteral("--family"), QStringLiteral("coming"),
                                      QStringLiteral("info")}),
                 2);
        Shell shell;
        shell.start(QStringLiteral("sim:throttle=0"), QStringLiteral("standard"));
        auto* families =
            shell.window()->connectionPage()->findChild<QComboBox*>(QStringLiteral("familyBox"));
        QVERIFY(families);
        const int coming = families->findData(QStringLiteral("coming"));
        QVERIFY(coming >= 0);
        const auto* model = qobject_cast<QStandardItemModel*>(families->model());
        QVERIFY(!(model->item(coming)->flags() & Qt::ItemIsEnabled));
        QVERIFY(families->itemText(coming).contains(QLatin1String("not built")));
    }

    void guiHostsTheFamily() {
        Shell shell;
        shell.start(QStringLiteral("sim:throttle=0"), QStringLiteral("fake-line"));
        MainWindow* window = shell.window();
        QSignalSpy loaded(window, &MainWindow::loaded);
        QVERIFY(loaded.wait(kTimeoutMs));
        QVERIFY(loaded.first().first().toBool());
        QVERIFY2(window->lastMessage().contains(QLatin1String("FAKE-1 simulated")),
                 qPrintable(window->lastMessage()));
        QCOMPARE(window->connectionPage()->family(), QStringLiteral("fake"));

        // Its page shows; the CamCon's hide.
        QListWidgetItem* fakeItem = navItem(window, QStringLiteral("Fake device"));
        QVERIFY(fakeItem);
        QVERIFY(!fakeItem->isHidden());
        QListWidgetItem* cams = navItem(window, QStringLiteral("Cam programs"));
        QVERIFY(cams);
        QVERIFY(cams->isHidden());
        QVERIFY(!window->findChild<QListWidget*>()->item(MainWindow::Connection)->isHidden());
        // So do the menu entries: its own shows, the CamCon's Compare hides.
        auto* ping = window->findChild<QAction*>(QStringLiteral("fakePingAction"));
        QVERIFY(ping && ping->isVisible());
        QAction* compare = menuEntry(window, QStringLiteral("Co&mpare with device…"));
        QVERIFY(compare && !compare->isVisible());
        // The connection strip names the device as the family identified it.
        QVERIFY2(window->connectionStrip()->text().contains(QLatin1String("FAKE-1")),
                 qPrintable(window->connectionStrip()->text()));

        // The page works with its device through the worker.
        const int before = fake::requestsReceived();
        window->findChild<QListWidget*>()->setCurrentItem(fakeItem);
        auto* page = window->findChild<QWidget*>(QStringLiteral("fakePage"));
        QVERIFY(page && page->isVisible());
        page->findChild<QPushButton*>(QStringLiteral("fakePing"))->click();
        auto* answer = page->findChild<QLabel*>(QStringLiteral("fakeAnswer"));
        QTRY_COMPARE_WITH_TIMEOUT(answer->text(), QStringLiteral("PONG 7"), kTimeoutMs);
        QVERIFY(fake::requestsReceived() > before);

        // Back to a CamCon: its pages return, the fake page hides.
        QVERIFY(connectVia(shell, QStringLiteral("standard")));
        QVERIFY(fakeItem->isHidden());
        QVERIFY(!cams->isHidden());
        QVERIFY(!ping->isVisible());
        QVERIFY(compare->isVisible());
        QCOMPARE(window->connectionPage()->family(), QStringLiteral("camcon"));
    }

    // The tour connects to each device a family names for it and saves
    // "<visit>-<stop>.png"; the shell names no family.
    void screenshotTourVisitsTheFamilysStops() {
        QSettings().clear();  // no connection remembered: the tour connects itself
        Shell shell;
        shell.start(QString());
        QTemporaryDir dir;
        ScreenshotTour tour(&shell, dir.path());
        tour.keepOnly({QStringLiteral("fake")});
        QCOMPARE(tour.plannedFiles(), QStringList{QStringLiteral("fake-01-fake.png")});
        QSignalSpy finished(&tour, &ScreenshotTour::finished);
        tour.start();
        QVERIFY(finished.wait(kTimeoutMs));
        QVERIFY2(finished.first().first().toBool(), qPrintable(tour.failures().join('\n')));
        QCOMPARE(tour.saved(), QStringList{QStringLiteral("fake-01-fake.png")});
        QVERIFY(QFileInfo::exists(dir.filePath(QStringLiteral("fake-01-fake.png"))));
        QCOMPARE(shell.window()->connectionPage()->family(), QStringLiteral("fake"));
    }

    // A device the tour cannot reach fails it, naming each stop not taken.
    void screenshotTourFailsNamingWhatItCouldNotReach() {
        QSettings().clear();
        Shell shell;
        shell.start(QString());
        QTemporaryDir dir;
        ScreenshotTour tour(&shell, dir.path());
        tour.keepOnly({QStringLiteral("fake-unreachable")});
        tour.setPatience(1000);  // the tour's patience, not a pass/fail time
        QSignalSpy finished(&tour, &ScreenshotTour::finished);
        tour.start();
        QVERIFY(finished.wait(kTimeoutMs));
        QCOMPARE(finished.first().first().toBool(), false);
        QVERIFY(tour.saved().isEmpty());
        QCOMPARE(tour.failures().size(), 1);
        QVERIFY2(tour.failures().first().contains(QStringLiteral("fake-unreachable-01-fake")),
                 qPrintable(tour.failures().first()));
    }

    // Every family and protocol with pages of its own is visited, each
    // page once, under a name that says family, protocol and page.
    void screenshotTourPlansEveryFamilysPages() {
        Shell shell;
        shell.start(QString());
        ScreenshotTour tour(&shell, QDir::tempPath());
        QMap<QString, QStringList> planned;  // visit -> its stops
        for (const QString& file : tour.plannedFiles()) {
            const qsizetype stop = file.indexOf(QRegularExpression(QStringLiteral("-\\d\\d-")));
            QVERIFY2(stop > 0 && file.endsWith(QStringLiteral(".png")), qPrintable(file));
            planned[file.left(stop)] << file.mid(stop + 1).chopped(4);
        }
        const QMap<QString, QStringList> expected{
            {QStringLiteral("camcon-standard"),
             {QStringLiteral("01-connection"), QStringLiteral("02-cam-editor"),
              QStringLiteral("03-dead-times"), QStringLiteral("04-settings"),
              QStringLiteral("05-users"), QStringLiteral("06-plc"), QStringLiteral("07-monitor"),
              QStringLiteral("08-compare"), QStringLiteral("09-backup-wizard"),
              QStringLiteral("10-terminal"), QStringLiteral("11-compare-programs"),
              QStringLiteral("12-timing-at-speed")}},
            {QStringLiteral("camcon-3964r-n96"),
             {QStringLiteral("01-connection"), QStringLiteral("02-dead-time-modes"),
              QStringLiteral("03-analogue-cams"), QStringLiteral("04-programming-program"),
              QStringLiteral("05-eeprom-lock"), QStringLiteral("06-plc-coupling")}},
            {QStringLiteral("camcon-cambus"),
             {QStringLiteral("01-connection"), QStringLiteral("02-cam-editor")}},
            {QStringLiteral("mc1"),
             {QStringLiteral("01-variables"), QStringLiteral("02-flags-io"),
              QStringLiteral("03-program"), QStringLiteral("04-axes"), QStringLiteral("05-memory"),
              QStringLiteral("06-trend")}},
            {QStringLiteral("mc1-ascii"),
             {QStringLiteral("01-variables"), QStringLiteral("02-flags-io")}},
            {QStringLiteral("compax3"),
             {QStringLiteral("01-objects"), QStringLiteral("02-status"),
              QStringLiteral("03-motion"), QStringLiteral("04-watch"),
              QStringLiteral("05-parameters")}},
            {QStringLiteral("compax3-rs485"),
             {QStringLiteral("01-connection"), QStringLiteral("02-status")}},
            {QStringLiteral("fake"), {QStringLiteral("01-fake")}},
            {QStringLiteral("fake-unreachable"), {QStringLiteral("01-fake")}},
        };
        QCOMPARE(planned, expected);
    }

    void cliHostsTheFamily() {
        const int before = fake::requestsReceived();
        QCOMPARE(cli::runCommandLine({QStringLiteral("--family"), QStringLiteral("fake"),
                                      QStringLiteral("ping"), QStringLiteral("5")}),
                 0);
        QVERIFY(fake::requestsReceived() > before);
        // Its command names its family (issue 39): no --family needed...
        QCOMPARE(cli::runCommandLine({QStringLiteral("ping"), QStringLiteral("5")}), 0);
        // ...and another family named with it is refused (usage).
        QCOMPARE(cli::runCommandLine({QStringLiteral("--family"), QStringLiteral("camcon"),
                                      QStringLiteral("ping"), QStringLiteral("5")}),
                 2);
        // And the CamCon's commands are not the fake's.
        QCOMPARE(cli::runCommandLine(
                     {QStringLiteral("--family"), QStringLiteral("fake"), QStringLiteral("info")}),
                 2);
    }

private:
    QTemporaryDir m_settings;
};

QTEST_MAIN(TestFakeFamily)
#include "tst_fake_family.moc"
