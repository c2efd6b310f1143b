// Issue 28 item 4: a family switch or another device leaves nothing of the
// device before on any page. Real widgets, the in-process simulator through
// the real worker, switched as a person does on the connection page:
// Compax3 drive S025V2 -> MC200 -> MC100 -> Compax3 drive S150V4. Each
// result line, identity and facts of a device is gone once another comes,
// on the pages of the family left as on those of the family that stays.
// Also item 6: messages composed from comm/'s lower-case parts read as
// sentences.
#include "shell_fixture.h"

#include "ui/compax3/compax3_object_model.h"
#include "ui/compax3/compax3_objects_page.h"
#include "ui/compax3/compax3_window.h"
#include "ui/device_session.h"
#include "ui/family_gui.h"
#include "ui/live_device_page.h"
#include "ui/mc1/mc1_variables_page.h"
#include "ui/mc1/mc1_watch_model.h"
#include "ui/mc1/mc1_window.h"
#include "ui/sentence.h"

#include "comm/compax3/compax3_objects.h"
#include "comm/mc1/mc1_variant.h"

#include <QLabel>
#include <QPushButton>
#include <QStatusBar>

using namespace cambench;
using namespace cambench::test;

namespace {

QString resultOf(const QWidget* page) {
    const auto* line = page->findChild<QLabel*>(QStringLiteral("pageResult"));
    return line ? line->text() : QString();
}

// The result lines of every family's pages that say `text`, with the
// page's title (a line about the new device, "The MC100 V2 has no memory
// telegrams", is that device's and may stay).
QStringList saying(const MainWindow* window, const QString& text) {
    QStringList shown;
    for (const LiveDevicePage* page : window->findChildren<LiveDevicePage*>())
        if (resultOf(page).contains(text))
            shown << page->sectionTitle() + QStringLiteral(": ") + resultOf(page);
    return shown;
}

// Connects to `port` with `protocol` as a person does on the connection
// page; true once the family has read the device.
bool switchTo(Shell& shell, const QString& port, const QString& protocol) {
    ConnectionPage* page = shell.window()->connectionPage();
    page->setPort(port);
    page->setProtocol(protocol);
    QSignalSpy loaded(shell.window(), &MainWindow::loaded);
    // Leaving a drive, or an MC200 read through the guessed parameter
    // numbers, asks first: "not moving" is no fact there (issue 35).
    auto leave = answerLeaveQuestion(QStringLiteral("leaveWithoutStop"));
    shell.window()->connectAndLoad();
    return loaded.wait(kDeviceTimeoutMs) && loaded.first().first().toBool();
}

}  // namespace

class FamilySwitchTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { useTestSettings(); }

    void nothingOfTheDeviceBeforeStays() {
        std::unique_ptr<Shell> shell =
            startOnSimulator(QStringLiteral("sim"), QStringLiteral("compax3"));
        QVERIFY(shell);
        MainWindow* window = shell->window();
        Compax3Window* c3 = compax3Window(window);
        Mc1Window* mc1 = mc1Window(window);
        QVERIFY(c3 && mc1);
        QCOMPARE(c3->facts().identity.type(), QStringLiteral("S025V2"));

        // Drive A: a refused entry leaves a red line on the Objects page.
        Compax3ObjectsPage* objects = c3->objectsPage();
        window->showPage(objects);
        Compax3ObjectModel* model = objects->model();
        const Compax3ObjectId target = comm::compax3SetTarget(2);
        QVERIFY(QTest::qWaitFor([&] { return model->driveValue(target).has_value(); },
                                kDeviceTimeoutMs));
        QVERIFY(model->setData(model->indexOf(target, Compax3ObjectModel::NewValue),
                               QStringLiteral("12,5")));
        const QString refused = resultOf(objects);
        QVERIFY(!refused.isEmpty());

        // To an MC200: nothing of the drive is said any more, on any page.
        QVERIFY(switchTo(*shell, QStringLiteral("sim:variant=mc200v2"), QStringLiteral("mc1")));
        QVERIFY2(saying(window, refused).isEmpty(), qPrintable(saying(window, refused).join('\n')));
        QVERIFY(!c3->facts().known);
        QVERIFY(c3->gui()->identityLine().isEmpty());
        QCOMPARE(mc1->facts().variant, comm::Mc1Variant::Mc200V2);

        // On the MC200: V2 = 77 written.
        window->showPage(mc1->variablesPage());
        Mc1WatchModel* watch = mc1->variablesPage()->model();
        QVERIFY(QTest::qWaitFor([&] { return watch->entries().value(1).value.has_value(); },
                                kDeviceTimeoutMs));
        {
            auto yes = answerConfirmation(true);
            watch->setData(watch->index(1, Mc1WatchModel::ValueColumn), 77, Qt::EditRole);
            QVERIFY(QTest::qWaitFor([&] { return *watch->entries().at(1).value == 77; },
                                    kDeviceTimeoutMs));
        }
        QVERIFY2(resultOf(mc1->variablesPage()).contains(QLatin1String("V2 = 77 written")),
                 qPrintable(resultOf(mc1->variablesPage())));

        // Another controller of the same family: the MC200's write is not
        // said of the MC100, and the facts are the MC100's.
        QVERIFY(switchTo(*shell, QStringLiteral("sim:variant=mc100v2"), QStringLiteral("mc1")));
        QVERIFY2(saying(window, QStringLiteral("V2 = 77")).isEmpty(),
                 qPrintable(saying(window, QStringLiteral("V2 = 77")).join('\n')));
        QCOMPARE(mc1->facts().variant, comm::Mc1Variant::Mc100V2);

        // Back to a drive of another type: the controller's facts go.
        QVERIFY(switchTo(*shell, QStringLiteral("sim:type=S150V4"), QStringLiteral("compax3")));
        QVERIFY2(saying(window, QStringLiteral("MC100 V2")).isEmpty(),
                 qPrintable(saying(window, QStringLiteral("MC100 V2")).join('\n')));
        QVERIFY(!mc1->facts().known);
        QVERIFY(mc1->gui()->identityLine().isEmpty());
        QCOMPARE(c3->facts().identity.type(), QStringLiteral("S150V4"));

        // A connect to another controller where nothing answers: offline,
        // the title and the pages no longer speak of the drive.
        const QString drive = c3->gui()->windowSubject();
        QVERIFY(!drive.isEmpty());
        QVERIFY2(window->windowTitle().contains(drive), qPrintable(window->windowTitle()));
        window->showPage(objects);
        QVERIFY(model->setData(model->indexOf(target, Compax3ObjectModel::NewValue),
                               QStringLiteral("12,5")));
        QVERIFY(!resultOf(objects).isEmpty());
        ConnectionPage* page = window->connectionPage();
        page->setPort(QStringLiteral("/dev/cambench-no-such-port"));
        page->setProtocol(QStringLiteral("mc1"));
        auto leave = answerLeaveQuestion();
        window->connectAndLoad();
        QTRY_VERIFY_WITH_TIMEOUT(shell->session()->state() == comm::ConnectionState::Disconnected,
                                 kDeviceTimeoutMs);
        QVERIFY2(!window->windowTitle().contains(drive), qPrintable(window->windowTitle()));
        QVERIFY2(saying(window, refused).isEmpty(), qPrintable(saying(window, refused).join('\n')));
        QVERIFY(!c3->facts().known);
        // The connection controls stay, whatever the family.
        for (const char* button : {"Connect", "Disconnect"}) {
            bool found = false;
            for (const QPushButton* b : page->findChildren<QPushButton*>())
                found = found || (b->text() == QLatin1String(button) && !b->isHidden());
            QVERIFY2(found, button);
        }
    }

    // From a drive to the CamCon on the same simulated port: the drive's
    // pages send nothing once another family is chosen (the Motion page
    // read its set when the STOP's reach changed, as soon as the family
    // was picked on the connection page, and said "Set 1 not read: the
    // connection speaks standard" under the CamCon's pages).
    void aSwitchToTheCamConAsksNothingOfIt() {  // from a Compax3 drive, then from an MC200
        std::unique_ptr<Shell> shell =
            startOnSimulator(QStringLiteral("sim"), QStringLiteral("compax3"));
        QVERIFY(shell);
        MainWindow* window = shell->window();
        Compax3Window* c3 = compax3Window(window);
        QVERIFY(c3 && c3->facts().known);
        // Every message the status bar showed, also those a later one hid.
        QStringList messages;
        connect(window->statusBar(), &QStatusBar::messageChanged, this,
                [&messages](const QString& message) { messages << message; });
        const auto nothingSaid = [window, &messages] {
            const QStringList notRead = messages.filter(QStringLiteral("not read"));
            QVERIFY2(notRead.isEmpty(), qPrintable(notRead.join('\n')));
            QVERIFY2(saying(window, QStringLiteral("not read")).isEmpty(),
                     qPrintable(saying(window, QStringLiteral("not read")).join('\n')));
        };
        // The family picked, not yet connected.
        window->connectionPage()->setProtocol(QStringLiteral("standard"));
        QTest::qWait(500);  // what a drive page might send has come back
        nothingSaid();
        QVERIFY(switchTo(*shell, QStringLiteral("sim"), QStringLiteral("standard")));
        QTest::qWait(500);
        QVERIFY(!c3->facts().known);
        nothingSaid();
        // The same from an MC200 with its axes.
        QVERIFY(switchTo(*shell, QStringLiteral("sim:variant=mc200v2"), QStringLiteral("mc1")));
        messages.clear();
        window->connectionPage()->setProtocol(QStringLiteral("standard"));
        QTest::qWait(500);
        nothingSaid();
        QVERIFY(switchTo(*shell, QStringLiteral("sim"), QStringLiteral("standard")));
        QTest::qWait(500);
        nothingSaid();
    }

    // "is lost. the port …": each sentence of a composed message starts
    // with a capital; an abbreviation's full stop ends none.
    void composedMessagesReadAsSentences() {
        QCOMPARE(asSentence(QStringLiteral("no reply. the port /dev/ttyUSB0 is gone")),
                 QStringLiteral("no reply. The port /dev/ttyUSB0 is gone."));
        QCOMPARE(asSentence(QStringLiteral("the answer was lost! it was not sent again")),
                 QStringLiteral("the answer was lost! It was not sent again."));
        QCOMPARE(asSentence(QStringLiteral("use another port (e.g. tcp://host:4001)")),
                 QStringLiteral("use another port (e.g. tcp://host:4001)."));
        QCOMPARE(asSentence(QStringLiteral("write 12.5 mm, etc. then press Write")),
                 QStringLiteral("write 12.5 mm, etc. then press Write."));
        QCOMPARE(capitalised(asSentence(QStringLiteral("über 3 ms. ändern"))),
                 QStringLiteral("Über 3 ms. Ändern."));
    }
};

QTEST_MAIN(FamilySwitchTest)
#include "tst_family_switch.moc"
