// The CamCon's backup wizard against the in-process simulator: a backup
// restored (with a safety backup first), another device's image only as
// its replacement, a damaged image refused.
#include "camcon_fixture.h"

#include "model/camcon/eeprom_image_file.h"
#include "ui/camcon/backup_wizard.h"
#include "ui/language.h"
#include "ui/progress_page.h"

#include <QAbstractButton>
#include <QFile>
#include <QMessageBox>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

using namespace cambench;
using namespace cambench::test;

class BackupWizardTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    // As the application does at start: English catalogue (plural forms).
    void initTestCase() {
        useTestSettings();
        QVERIFY(setLanguage(QStringLiteral("en")));
    }
    void backupAndRestoreThroughWizard();
    void wizardRestoresAnotherDevicesImageOnlyAsItsReplacement();
    void restoreRefusesDamagedImage();
};

void BackupWizardTest::backupAndRestoreThroughWizard() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString image = dir.filePath(QStringLiteral("backup.json"));
    const QString safety = dir.filePath(QStringLiteral("safety.json"));

    BackupWizard* backup = camConWindow(shell->window())->openBackupWizard();
    backup->setMode(BackupWizard::Mode::Backup);
    backup->setPath(image);
    backup->next();
    QCOMPARE(backup->currentId(), int(BackupWizard::RunPage));
    QTRY_VERIFY_WITH_TIMEOUT(backup->progressPage()->isComplete(), kDeviceTimeoutMs);
    QVERIFY2(backup->progressPage()->reportText().contains(QStringLiteral("Backup complete")),
             qPrintable(backup->progressPage()->reportText()));
    QVERIFY(loadEepromImage(image).ok());
    backup->close();

    BackupWizard* restore = camConWindow(shell->window())->openBackupWizard();
    QSignalSpy restored(restore, &BackupWizard::restored);
    restore->setMode(BackupWizard::Mode::Restore);
    restore->setPath(image);
    restore->next();
    QCOMPARE(restore->currentId(), int(BackupWizard::CheckPage));
    QVERIFY(restore->checkText().contains(QStringLiteral("matches")));
    restore->setSafetyBackupPath(safety);
    NextDialog<QMessageBox> erase([](QMessageBox* box) {
        for (QAbstractButton* button : box->buttons()) {
            if (box->buttonRole(button) == QMessageBox::DestructiveRole) button->click();
        }
    });
    restore->next();
    QCOMPARE(erase.answered(), 1);
    QTRY_VERIFY_WITH_TIMEOUT(restore->progressPage()->isComplete(), kDeviceTimeoutMs);
    const QString report = restore->progressPage()->reportText();
    QVERIFY2(report.contains(QStringLiteral("Restore complete")), qPrintable(report));
    QVERIFY(report.contains(QStringLiteral("0 failed")));
    QCOMPARE(restored.size(), 1);
    QVERIFY(loadEepromImage(safety).ok());
    restore->close();
}

// Issue 35, item 8: an image of another device (here device number 5) is
// restored only when the person says this device replaces that one; the
// question shows both identities. Declined, the wizard stays and nothing is
// erased; accepted, the erase question follows and the restore runs.
void BackupWizardTest::wizardRestoresAnotherDevicesImageOnlyAsItsReplacement() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QTemporaryDir dir;
    const QString image = dir.filePath(QStringLiteral("other.json"));
    BackupWizard* backup = camConWindow(shell->window())->openBackupWizard();
    backup->setMode(BackupWizard::Mode::Backup);
    backup->setPath(image);
    backup->next();
    QTRY_VERIFY_WITH_TIMEOUT(backup->progressPage()->isComplete(), kDeviceTimeoutMs);
    backup->close();
    Result<EepromImage> taken = loadEepromImage(image);
    QVERIFY(taken.ok());
    EepromImage other = *taken;
    other.device.deviceNumber = 5;
    QVERIFY(saveEepromImage(image, other).ok());

    BackupWizard* restore = camConWindow(shell->window())->openBackupWizard();
    QSignalSpy restored(restore, &BackupWizard::restored);
    restore->setMode(BackupWizard::Mode::Restore);
    restore->setPath(image);
    restore->next();
    QCOMPARE(restore->currentId(), int(BackupWizard::CheckPage));
    QVERIFY(restore->checkText().contains(QStringLiteral("does NOT match")));
    restore->setSafetyBackupPath(dir.filePath(QStringLiteral("safety.json")));
    QString question;
    {
        NextDialog<QMessageBox> decline([&question](QMessageBox* box) {
            question = box->objectName() + QLatin1Char('\n') + box->informativeText();
            box->button(QMessageBox::Cancel)->click();
        });
        restore->next();
        QCOMPARE(decline.answered(), 1);
    }
    QVERIFY2(question.startsWith(QStringLiteral("replacementQuestion")), qPrintable(question));
    QVERIFY2(question.contains(QStringLiteral("device: backup 5, this device 0  ← differs")),
             qPrintable(question));
    QCOMPARE(restore->currentId(), int(BackupWizard::CheckPage));
    QCOMPARE(restored.size(), 0);

    // Accepted: then the erase question, then the restore.
    QStringList asked;
    QTimer answer;
    answer.setInterval(10);
    connect(&answer, &QTimer::timeout, this, [&asked] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box) return;
        asked << box->objectName();
        for (QAbstractButton* button : box->buttons())
            if (box->buttonRole(button) == QMessageBox::DestructiveRole) {
                button->click();
                return;
            }
    });
    answer.start();
    restore->next();
    answer.stop();
    QCOMPARE(asked.size(), 2);
    QCOMPARE(asked.at(0), QStringLiteral("replacementQuestion"));
    QTRY_VERIFY_WITH_TIMEOUT(restore->progressPage()->isComplete(), kDeviceTimeoutMs);
    QVERIFY2(restore->progressPage()->reportText().contains(QStringLiteral("Restore complete")),
             qPrintable(restore->progressPage()->reportText()));
    QCOMPARE(restored.size(), 1);
    restore->close();
}

void BackupWizardTest::restoreRefusesDamagedImage() {
    auto shell = startOnSimulator();
    QVERIFY(shell);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("damaged.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{\"format\":\"cambench-eeprom-image\",\"version\":1,\"blocks\":[]}");
    file.close();
    BackupWizard* restore = camConWindow(shell->window())->openBackupWizard();
    restore->setMode(BackupWizard::Mode::Restore);
    restore->setPath(path);
    // The refusal is a message box; answer it so the test goes on.
    QTimer::singleShot(0, restore, [] {
        if (QWidget* box = QApplication::activeModalWidget()) box->close();
    });
    restore->next();
    QCOMPARE(restore->currentId(), int(BackupWizard::ChoosePage));
    restore->close();
}

QTEST_MAIN(BackupWizardTest)
#include "tst_backup_wizard.moc"
