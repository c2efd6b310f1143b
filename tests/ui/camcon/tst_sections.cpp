// The CamCon's sections per protocol against the in-process simulator: a
// dead time written in tenths of a millisecond; the sections a protocol
// lacks greyed with the reason; the table interface's own data (dead-time
// modes, analogue cams) written and read back, asked about before a read
// replaces an edit; a locked EEPROM said plainly.
#include "camcon_fixture.h"

#include "ui/camcon/analogue_cams_page.h"
#include "ui/camcon/dead_time_modes_page.h"
#include "ui/camcon/dead_times_model.h"
#include "ui/camcon/dead_times_page.h"
#include "ui/camcon/eeprom_lock_page.h"
#include "ui/language.h"

#include <QMessageBox>
#include <QPushButton>
#include <QtTest>

using namespace cambench;
using namespace cambench::test;

class SectionsTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    // As the application does at start: English catalogue (plural forms).
    void initTestCase() {
        useTestSettings();
        QVERIFY(setLanguage(QStringLiteral("en")));
    }
    void deadTimeEditIsWrittenInTenthsOfMs_data() { protocolRows(); }
    void deadTimeEditIsWrittenInTenthsOfMs();
    void sectionsFollowTheProtocolsCapabilities_data() { protocolRows(); }
    void sectionsFollowTheProtocolsCapabilities();
    void dataOnlyTheTableInterfaceHasIsEditedAndWritten();
    void tablePageAsksBeforeAReadReplacesEdits();
    void lockedEepromIsShownAsAPlainWarning();
};

void SectionsTest::deadTimeEditIsWrittenInTenthsOfMs() {
    QFETCH(QString, protocol);
    auto shell = startOnSimulator(QStringLiteral("sim:throttle=0"), protocol);
    QVERIFY(shell);
    QVERIFY(waitForSections(*shell));
    DeadTimesPage* page = camConWindow(shell->window())->deadTimesPage();
    DeadTimesModel* model = page->model();
    const QModelIndex cell = model->index(0, DeadTimesModel::DeadTimeColumn);
    QVERIFY(model->setData(cell, 12.3));
    QCOMPARE(camConWorkspace(*shell)->cams()->deadTime(1), 123);
    QVERIFY(model->data(cell).toString().startsWith(QStringLiteral("● ")));
    // Above the device's maximum (?GTZKMAX) is refused.
    QVERIFY(!model->setData(cell, camConWorkspace(*shell)->info().maxDeadTime / 10.0 + 0.1));

    std::optional<WriteResult> result;
    page->writeChanges([&](const WriteResult& r) { result = r; });
    QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), kDeviceTimeoutMs);
    QVERIFY(result->ok());
    QCOMPARE(result->value().count(usecases::WriteState::Written), 1);
    QVERIFY(result->value().complete());
    QVERIFY(!model->data(cell).toString().startsWith(QStringLiteral("● ")));

    page->readFromDevice();
    QTRY_COMPARE_WITH_TIMEOUT(camConWorkspace(*shell)->deviceDeadTime(1), 123, kDeviceTimeoutMs);
}

void SectionsTest::sectionsFollowTheProtocolsCapabilities() {
    QFETCH(QString, protocol);
    auto shell = startOnSimulator(QStringLiteral("sim:throttle=0"), protocol);
    QVERIFY(shell);
    MainWindow* window = shell->window();
    const bool ascii = protocol == QLatin1String("standard");
    CapabilityGate* users = gateOf(window, camConWindow(window)->usersPage());
    CapabilityGate* modes = gateOf(window, window->findChild<DeadTimeModesPage*>());
    CapabilityGate* lock = gateOf(window, window->findChild<EepromLockPage*>());
    QVERIFY(users && modes && lock);
    QTRY_COMPARE_WITH_TIMEOUT(users->isAvailable(), ascii, kDeviceTimeoutMs);
    QTRY_COMPARE_WITH_TIMEOUT(lock->isAvailable(), !ascii, kDeviceTimeoutMs);
    // 3964R e38 cannot address the dead-time mode words.
    QTRY_COMPARE_WITH_TIMEOUT(modes->isAvailable(), protocol == QLatin1String("3964r-n96"),
                              kDeviceTimeoutMs);
    // A section the protocol lacks says which protocol has it.
    const QString why = ascii ? modes->reason() : users->reason();
    QVERIFY2(why.contains(ascii ? QLatin1String("table interface") : QLatin1String("ASCII")),
             qPrintable(why));
    if (protocol == QLatin1String("3964r-e38"))
        QVERIFY2(modes->reason().contains(QLatin1String("3964R n96")), qPrintable(modes->reason()));
    // The Device menu's backups follow the Backup section.
    QAction* backup = nullptr;
    for (QAction* action : window->findChildren<QAction*>())
        if (action->text() == QStringLiteral("&Backup and restore…")) backup = action;
    QVERIFY(backup);
    QTRY_COMPARE_WITH_TIMEOUT(backup->isEnabled(), ascii, kDeviceTimeoutMs);
}

void SectionsTest::dataOnlyTheTableInterfaceHasIsEditedAndWritten() {
    auto shell = startOnSimulator(QStringLiteral("sim:throttle=0"), QStringLiteral("3964r-n96"));
    QVERIFY(shell);
    auto* modes = shell->window()->findChild<DeadTimeModesPage*>();
    QTRY_VERIFY_WITH_TIMEOUT(modes->onDevice().size() == 32, kDeviceTimeoutMs);
    QCOMPARE(modes->edited(2).mode, DeadTimeMode::SeparateOnOff);
    const OutputDeadTime wanted{DeadTimeMode::SeparateOnOff, 0, 35, 47};
    modes->setEdited(5, wanted);
    QCOMPARE(modes->differences().size(), 1);
    std::optional<WriteResult> result;
    modes->writeChanges([&](const WriteResult& r) { result = r; });
    QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), kDeviceTimeoutMs);
    QVERIFY2(result->ok() && (*result)->complete(), qPrintable(writeDetails(*result)));
    QCOMPARE((*result)->count(usecases::WriteState::Written), 1);
    modes->setEdited(5, {});
    modes->readFromDevice();
    QTRY_COMPARE_WITH_TIMEOUT(modes->edited(5), wanted, kDeviceTimeoutMs);
    QVERIFY(modes->differences().isEmpty());

    auto* analogue = shell->window()->findChild<AnalogueCamsPage*>();
    QTRY_COMPARE_WITH_TIMEOUT(analogue->onDevice().points.size(), 3, kDeviceTimeoutMs);
    const AnalogueCamTrack curve{1, {{10, 100}, {20, 200}}};
    analogue->setEdited(curve);
    result.reset();
    analogue->writeChanges([&](const WriteResult& r) { result = r; });
    QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), kDeviceTimeoutMs);
    QVERIFY2(result->ok() && (*result)->complete(), qPrintable(writeDetails(*result)));
    QCOMPARE((*result)->count(usecases::WriteState::Written), 1);
    analogue->setEdited({1, {}});
    analogue->readFromDevice();
    QTRY_COMPARE_WITH_TIMEOUT(analogue->edited(), curve, kDeviceTimeoutMs);
}

void SectionsTest::tablePageAsksBeforeAReadReplacesEdits() {
    auto shell = startOnSimulator(QStringLiteral("sim:throttle=0"), QStringLiteral("3964r-n96"));
    QVERIFY(shell);
    auto* modes = shell->window()->findChild<DeadTimeModesPage*>();
    QTRY_VERIFY_WITH_TIMEOUT(modes->onDevice().size() == 32, kDeviceTimeoutMs);
    const OutputDeadTime edited{DeadTimeMode::SeparateOnOff, 0, 35, 47};
    modes->setEdited(5, edited);
    QPushButton* read = nullptr;
    for (QPushButton* button : modes->findChildren<QPushButton*>())
        if (button->text() == QLatin1String("Read from device")) read = button;
    QVERIFY(read);
    const auto answer = [](QMessageBox::StandardButton choice) {
        return NextDialog<QMessageBox>(
            [choice](QMessageBox* box) { box->button(choice)->click(); });
    };
    {
        auto no = answer(QMessageBox::No);
        read->click();
        QTRY_COMPARE_WITH_TIMEOUT(no.answered(), 1, kDeviceTimeoutMs);
    }
    QCOMPARE(modes->edited(5), edited);
    {
        auto yes = answer(QMessageBox::Yes);
        read->click();
        QTRY_COMPARE_WITH_TIMEOUT(yes.answered(), 1, kDeviceTimeoutMs);
    }
    QTRY_COMPARE_WITH_TIMEOUT(modes->edited(5), modes->onDevice().value(5), kDeviceTimeoutMs);
    QVERIFY(modes->differences().isEmpty());
}

void SectionsTest::lockedEepromIsShownAsAPlainWarning() {
    auto shell = startOnSimulator(QStringLiteral("sim:throttle=0"), QStringLiteral("3964r-e38"));
    QVERIFY(shell);
    auto* lock = shell->window()->findChild<EepromLockPage*>();
    QTRY_VERIFY_WITH_TIMEOUT(lock->locked().has_value(), kDeviceTimeoutMs);
    QVERIFY(!*lock->locked());
    QVERIFY(!lock->warningShown());
    lock->setLocked(true);
    QTRY_VERIFY_WITH_TIMEOUT(lock->locked().value_or(false), kDeviceTimeoutMs);
    QVERIFY(lock->warningShown());
    QVERIFY(lock->warningText().contains(QStringLiteral("RAM only")));
    QVERIFY2(shell->window()->lastMessage().contains(QStringLiteral("RAM only")),
             qPrintable(shell->window()->lastMessage()));
}

QTEST_MAIN(SectionsTest)
#include "tst_sections.moc"
