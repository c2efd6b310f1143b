// Issue 36 item 4: Machine -> Back up..., Verify..., Restore... in the
// machine window. Real widgets, three devices of the three families, each
// on its own in-process simulated device and its own worker (all at once):
// a bar and a result line per device, the manifest of the command line's
// folder, a value changed behind CamBench's back named by verify on its
// device's line and put back by the restore, every plan listed before the
// one question of a restore, and a device that was not done says so on
// its line. Then the machine report's section of each family.
#include "machine_fixture.h"
#include "shell_fixture.h"

#include "comm/mc1/mc1_device.h"
#include "model/file_read.h"
#include "model/machine/machine_backup_folder.h"
#include "ui/machine/machine.h"
#include "ui/machine/machine_backup_run.h"
#include "ui/machine/machine_progress.h"
#include "ui/machine/machine_report.h"
#include "ui/machine/machine_unit.h"
#include "ui/machine/machine_window.h"

#include <QDir>
#include <QFile>
#include <QMessageBox>
#include <QProgressBar>
#include <QTemporaryDir>
#include <QTextDocument>
#include <QTimer>

using namespace cambench;
using namespace cambench::test;

namespace {

const QStringList kNames{QStringLiteral("cams"), QStringLiteral("press-plc"),
                         QStringLiteral("feed")};

// A device of each family open in a machine's window; a backup folder's path.
std::unique_ptr<OpenedMachine> openThreeFamilies() {
    return openWithBackupFolder(threeFamilies(), QStringLiteral("press-backup"));
}

}  // namespace

class TestMachineBackup : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { useTestSettings(); }

    void backsUpVerifiesAndRestoresEveryDevice() {
        const std::unique_ptr<OpenedMachine> open = openThreeFamilies();
        QVERIFY(waitIdentified(*open->machine));
        Machine* machine = open->machine;
        const QString dir = open->dir;

        // Back up: a bar and a line per device, the command line's folder.
        MachineBackupRun* backup = machine->window()->backUpTo(dir, QStringLiteral("before the "
                                                                                   "new knife"));
        QCOMPARE(backup->progress()->names(), kNames);
        for (const QString& name : kNames) QVERIFY(backup->progress()->bar(name));
        QVERIFY(waitDone(backup));
        for (const QString& name : kNames)
            QVERIFY2(backup->progress()->resultLine(name).startsWith(QLatin1String("saved: ")),
                     qPrintable(name + QLatin1String(": ") + backup->progress()->resultLine(name)));
        const MachineManifest manifest = manifestIn(dir);
        QCOMPARE(manifest.devices.size(), 3);
        for (const ManifestEntry& entry : manifest.devices) {
            QVERIFY2(entry.saved(), qPrintable(entry.result));
            QVERIFY(entry.identity.known());
            QVERIFY(QFile::exists(QDir(dir).filePath(entry.file)));
        }
        QCOMPARE(manifest.author.note, QStringLiteral("before the new knife"));
        QVERIFY(!manifest.author.operatorName.isEmpty());
        QVERIFY(!manifest.author.tool.isEmpty());
        QVERIFY(QFile::exists(QDir(dir).filePath(kMachineBackupFile)));

        // Verify: each device equal, in its own line.
        MachineBackupRun* verify = machine->window()->verifyFrom(dir);
        QVERIFY(waitDone(verify));
        for (const QString& name : kNames)
            QVERIFY2(verify->progress()->resultLine(name).startsWith(QLatin1String("equal: ")),
                     qPrintable(name + QLatin1String(": ") + verify->progress()->resultLine(name)));

        // V12 of the MC200 changes behind CamBench's back: verify names it
        // in the family's words on that device's line only.
        Result<Done> changed = Error::communication(QStringLiteral("not run"));
        machine->unit(QStringLiteral("press-plc"))
            ->session()
            ->run<comm::Mc1Device, Done>(
                open->machine, QStringLiteral("change V12"),
                [](comm::Mc1Device& device, comm::JobContext&) -> Result<Done> {
                    return device.writeVariable(12, 77);
                },
                [&changed](Result<Done> done) { changed = done; });
        QVERIFY(QTest::qWaitFor([&] { return changed.ok(); }, kDeviceTimeoutMs));
        MachineBackupRun* differs = machine->window()->verifyFrom(dir);
        QVERIFY(waitDone(differs));
        const QString plcLine = differs->progress()->resultLine(QStringLiteral("press-plc"));
        QCOMPARE(plcLine, QString::fromUtf8("1 difference(s):\npress-plc: V12 0 → 77"));
        for (const char* name : {"cams", "feed"})
            QVERIFY(differs->progress()
                        ->resultLine(QLatin1String(name))
                        .startsWith(QLatin1String("equal: ")));

        // Restore: every device's plan in the one question before a byte.
        QString asked;
        QString plans;
        NextDialog<QMessageBox> answer([&](QMessageBox* box) {
            asked = box->objectName();
            plans = box->detailedText();
            for (QAbstractButton* button : box->buttons())
                if (box->buttonRole(button) == QMessageBox::DestructiveRole) button->click();
        });
        MachineBackupRun* restore = machine->window()->restoreFrom(dir);
        QVERIFY(waitDone(restore));
        QCOMPARE(asked, QStringLiteral("machineRestoreQuestion"));
        for (const QString& name : kNames) {
            QVERIFY2(plans.contains(name + QLatin1String(": ")), qPrintable(plans));
            const QString line = restore->progress()->resultLine(name);
            QVERIFY2(line.startsWith(QLatin1String("restored: ")), qPrintable(name + ": " + line));
        }
        QVERIFY2(plans.contains(QLatin1String("V12")), qPrintable(plans));
        MachineBackupRun* equal = machine->window()->verifyFrom(dir);
        QVERIFY(waitDone(equal));
        QVERIFY(equal->progress()
                    ->resultLine(QStringLiteral("press-plc"))
                    .startsWith(QLatin1String("equal: ")));
        // The safety copies beside the backup folder, listed.
        QVERIFY(!restore->safetyFolder().isEmpty());
        QVERIFY(!restore->safetyFolder().startsWith(dir + QLatin1Char('/')));
        const MachineManifest safety = manifestIn(restore->safetyFolder());
        QVERIFY(!safety.devices.isEmpty());
        QCOMPARE(safety.safetyCopyOf, QDir(dir).absolutePath());

        // The report after the restore: every device read again, each
        // family its own section.
        MachineProgress* read =
            machine->window()->writeReportTo(open->folder.filePath(QStringLiteral("press.pdf")));
        QSignalSpy readDone(read, &MachineProgress::finished);
        QVERIFY(readDone.wait(kDeviceTimeoutMs));
        for (const QString& name : kNames) QCOMPARE(read->resultLine(name), QStringLiteral("read"));
        QTextDocument document;
        MachineReport::build(document, *machine);
        const QString text = document.toPlainText();
        for (const char* part : {"Commissioning report", "PLC program", "Variables",
                                 "Parameter set", "Set 1 velocity"})
            QVERIFY2(text.contains(QLatin1String(part)), part);
    }

    // A device the backup does not hold is not verified and not restored,
    // one the person does not accept as the backup's is not restored, and
    // each line says so; the others go on. Nothing says "done" for them.
    void eachDeviceNotDoneSaysSo() {
        const std::unique_ptr<OpenedMachine> open = openThreeFamilies();
        QVERIFY(waitIdentified(*open->machine));
        Machine* machine = open->machine;
        const QString dir = open->dir;
        QVERIFY(waitDone(machine->window()->backUpTo(dir, {})));
        MachineManifest manifest = manifestIn(dir);
        manifest.devices.removeIf(
            [](const ManifestEntry& entry) { return entry.name == QLatin1String("feed"); });
        // The MC200's backup was taken from another controller.
        for (ManifestEntry& entry : manifest.devices)
            if (entry.name == QLatin1String("press-plc"))
                entry.identity.set(entry.identity.values().firstKey(), QStringLiteral("other"));
        QVERIFY(rewriteManifest(dir, manifest));

        MachineBackupRun* verify = machine->window()->verifyFrom(dir);
        QVERIFY(waitDone(verify));
        QCOMPARE(verify->progress()->resultLine(QStringLiteral("feed")),
                 QStringLiteral("not verified: not in this backup"));
        QVERIFY(verify->progress()
                    ->resultLine(QStringLiteral("cams"))
                    .startsWith(QLatin1String("equal: ")));

        // Each question declined: the MC200 is not the backup's (its
        // identity's question), then the CamCon's restore is cancelled.
        const DeclineEveryQuestion declining;
        MachineBackupRun* restore = machine->window()->restoreFrom(dir);
        QVERIFY(waitDone(restore));
        QCOMPARE(declining.asked(), (QStringList{QStringLiteral("replacementQuestion"),
                                                 QStringLiteral("machineRestoreQuestion")}));
        QCOMPARE(restore->progress()->resultLine(QStringLiteral("feed")),
                 QStringLiteral("not restored: not in this backup"));
        const QString plc = restore->progress()->resultLine(QStringLiteral("press-plc"));
        QVERIFY2(plc.startsWith(QLatin1String("not restored: another device answers")),
                 qPrintable(plc));
        QCOMPARE(restore->progress()->resultLine(QStringLiteral("cams")),
                 QStringLiteral("not restored: cancelled, nothing was written"));
        QVERIFY(restore->safetyFolder().isEmpty());
    }
};

QTEST_MAIN(TestMachineBackup)
#include "tst_machine_backup.moc"
