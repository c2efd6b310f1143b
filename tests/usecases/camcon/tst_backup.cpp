// Backup, restore and verify of the EEPROM, and the backup of a whole
// Multiuser line, against the in-process simulator.
#include "sim_bench.h"

#include "comm/camcon/usecases/backup_restore.h"
#include "comm/camcon/usecases/line_backup.h"
#include "model/camcon/eeprom_image_file.h"
#include "model/file_read.h"

#include <QDir>
#include <QLoggingCategory>
#include <QTemporaryDir>
#include <QTest>

using namespace cambench;
using namespace cambench::comm;
using namespace cambench::usecases;
using cambench::tests::SimBench;

namespace {

bool writeFileBytes(const QString& path, const QByteArray& bytes) {
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

}  // namespace

class TestBackup : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void safetyBackupIsNamedAfterTheImageAndTime();
    void restoreTakesSafetyBackupThenRestores();
    void restoreOfForeignImageIsRefusedUnlessAcceptedAsReplacement();
    void restorePutsBackTheImagesCommunicationSettingsAndSaysSo();
    void failedRestoreSaysTheDeviceIsErased();
    void lineBackupGoesOnPastADeadDevice();
    void verifyLineComparesEverySavedDevice();
    void resumeSkipsDevicesAlreadySaved();
    void resumeDoesNotTrustAChangedImage();
};

void TestBackup::initTestCase() {
    QLoggingCategory::setFilterRules(
        QStringLiteral("cambench.*.debug=false\ncambench.comm.link.warning=false\n"
                       "cambench.comm.engine.warning=false"));
}

void TestBackup::safetyBackupIsNamedAfterTheImageAndTime() {
    QTemporaryDir dir;
    const QString image = dir.filePath(QStringLiteral("line7.json"));
    const QDateTime time(QDate(2026, 11, 21), QTime(23, 15, 0), Qt::UTC);
    const QString path = safetyBackupPath(image, time);
    QCOMPARE(path, image + QStringLiteral(".safety-20261121T231500Z.json"));
    QVERIFY(writeFileBytes(path, "x"));
    QCOMPARE(safetyBackupPath(image, time),
             image + QStringLiteral(".safety-20261121T231500Z-2.json"));
}

void TestBackup::restoreTakesSafetyBackupThenRestores() {
    SimBench bench;
    QTemporaryDir dir;
    const QString imagePath = dir.filePath(QStringLiteral("image.json"));
    const Result<EepromImage> image = backupToFile(*bench.client, imagePath);
    QVERIFY2(image.ok(), qPrintable(image.error().message));
    const SimState original = bench.device().state();
    QVERIFY(bench.client->writeTrack(2, Track{9, {{200, 220}}}).ok());

    const RestoreReport report = restoreImage(*bench.client, *image, imagePath);
    QVERIFY2(report.ok(), qPrintable(report.error.message));
    QVERIFY(report.safetyBackupPath.startsWith(imagePath + QStringLiteral(".safety-")));
    QVERIFY(report.safetyBackupPath.endsWith(QStringLiteral("Z.json")));
    QCOMPARE(bench.device().state().cams, original.cams);
    // The safety backup holds the changed device.
    const Result<EepromImage> safety = loadEepromImage(report.safetyBackupPath);
    QVERIFY(safety.ok());
    const Result<VerifyReport> verified = verifyImage(*bench.client, *safety);
    QVERIFY(verified.ok());
    QVERIFY(!verified->equal);
    QVERIFY(verifyImage(*bench.client, *image)->equal);
}

void TestBackup::restoreOfForeignImageIsRefusedUnlessAcceptedAsReplacement() {
    // Issue 35, item 8: an image goes only to the device it was taken from
    // (camConIdentity: EPROM date, device number, capacities, memories).
    SimBench bench;
    Result<EepromImage> image = backupDevice(*bench.client);
    QVERIFY(image.ok());
    const DeviceIdentity device = camConIdentity(image->device);
    image.value().device.outputs = 64;
    image.value().device.deviceNumber = 5;
    bench.commandsSent();
    RestoreOptions options;
    options.safetyBackup = false;
    const RestoreReport refused =
        restoreImage(*bench.client, *image, QStringLiteral("x.json"), options);
    QCOMPARE(refused.state, RestoredState::Unchanged);
    QCOMPARE(refused.error.kind, ErrorKind::InvalidData);
    // Both identities named, the differing values side by side.
    QVERIFY2(refused.error.message.contains(
                 QStringLiteral("another device answers: expected device 5, outputs 64, found "
                                "device %1, outputs %2")
                     .arg(device.value(QStringLiteral("device")),
                          device.value(QStringLiteral("outputs")))),
             qPrintable(refused.error.message));
    QVERIFY(refused.error.message.contains(QLatin1String("Nothing was written")));
    QVERIFY(refused.error.message.contains(QLatin1String("--replacement")));
    QCOMPARE(bench.commandsSent(), 0);  // no command: queries only
    // Accepted for another device than the one answering: refused too.
    DeviceIdentity other = device;
    other.set(QStringLiteral("ram"), QStringLiteral("1"));
    options.replacement = ReplacementConsent::of(other);
    QCOMPARE(restoreImage(*bench.client, *image, QStringLiteral("x.json"), options).state,
             RestoredState::Unchanged);
    options.replacement = ReplacementConsent::of(device);
    const RestoreReport accepted =
        restoreImage(*bench.client, *image, QStringLiteral("x.json"), options);
    QVERIFY2(accepted.ok(), qPrintable(accepted.error.message));
    QCOMPARE(accepted.identityMismatch.size(), 2);
}

// Issue 39: an image is the device's own byte image, its communication
// settings included. Restored after the device was set to another protocol
// and number, it puts back its own, and the report says what the next
// connection needs.
void TestBackup::restorePutsBackTheImagesCommunicationSettingsAndSaysSo() {
    SimBench bench;
    const Result<EepromImage> image = backupDevice(*bench.client);
    QVERIFY(image.ok());
    RestoreOptions options;
    options.safetyBackup = false;
    const RestoreReport same =
        restoreImage(*bench.client, *image, QStringLiteral("x.json"), options);
    QVERIFY2(same.ok(), qPrintable(same.error.message));
    QCOMPARE(same.linkNote, QString());
    const Result<SystemSettings> settings = bench.client->readSettings();
    QVERIFY(settings.ok());
    // (The simulator goes on speaking Standard; a real device would not.)
    QVERIFY(bench.client
                ->writeSettings({{QStringLiteral("protocol"), qint64(2)},
                                 {QStringLiteral("deviceNumber"), qint64(9)}},
                                *settings)
                .ok());
    // Its device number is part of a CamCon's identity (what tells devices
    // on one line apart): the person confirms it is the same device.
    options.replacement = ReplacementConsent::any();
    const RestoreReport back =
        restoreImage(*bench.client, *image, QStringLiteral("x.json"), options);
    QVERIFY2(back.ok(), qPrintable(back.error.message));
    QCOMPARE(back.linkNote,
             QStringLiteral("The image holds the communication settings the device had when it "
                            "was taken, Device number 0, Communication protocol Standard (it uses "
                            "Device number 9, Communication protocol Multiuser now). A restore "
                            "puts them back with everything else: the next connection to the "
                            "device needs Device number 0, Communication protocol Standard."));
    QCOMPARE(bench.client->readSetting(QStringLiteral("protocol"))->toLongLong(), 1);
    QCOMPARE(bench.client->readSetting(QStringLiteral("deviceNumber"))->toLongLong(), 0);
}

void TestBackup::failedRestoreSaysTheDeviceIsErased() {
    SimBench bench;
    const Result<EepromImage> image = backupDevice(*bench.client);
    QVERIFY(image.ok());
    // The third block is refused: the device is erased and partly written.
    bench.injections().refuse(0, '!', "EE", -46, 2);
    QTemporaryDir dir;
    const RestoreReport report =
        restoreImage(*bench.client, *image, dir.filePath(QStringLiteral("image.json")));
    QCOMPARE(report.state, RestoredState::ErasedOrPartial);
    QVERIFY2(report.error.message.contains(QLatin1String("ERASED")),
             qPrintable(report.error.message));
    QVERIFY(report.error.message.contains(report.safetyBackupPath));
    QVERIFY(QFile::exists(report.safetyBackupPath));
}

namespace {

// Devices 1, 2 and 3 on one Multiuser line, device 2 dead.
struct Line {
    Line() : bench({1, 2, 3}, Framing::Multiuser) { bench.injections().setDead(2, true); }
    SimBench bench;
    QTemporaryDir dir;

    Result<LineManifest> backup(bool resume = false) {
        LineBackupOptions options;
        options.directory = dir.path();
        options.devices = {1, 2, 3};
        options.resume = resume;
        options.lineDescription = QStringLiteral("test line");
        return backupLine(*bench.client, options);
    }
};

}  // namespace

void TestBackup::lineBackupGoesOnPastADeadDevice() {
    Line line;
    QList<int> progressDevices;
    LineBackupOptions options;
    options.directory = line.dir.path();
    options.devices = {1, 2, 3};
    const Result<LineManifest> manifest = backupLine(
        *line.bench.client, options, {}, [&](int device, qint64, qint64, const QString&) {
            if (!progressDevices.contains(device)) progressDevices << device;
        });
    QVERIFY2(manifest.ok(), qPrintable(manifest.error().message));
    QCOMPARE(manifest->devices.size(), 3);
    QVERIFY(!manifest->allSaved());
    const LineManifestEntry* one = manifest->find(1);
    const LineManifestEntry* two = manifest->find(2);
    QCOMPARE(one->outcome, LineManifestEntry::Outcome::Saved);
    QCOMPARE(one->file, QStringLiteral("device-01_11.10.1994_32out.json"));
    QCOMPARE(one->identity->deviceNumber, 1);
    QCOMPARE(two->outcome, LineManifestEntry::Outcome::Failed);
    QVERIFY(!two->message.isEmpty());
    QVERIFY(!two->identity);
    QCOMPARE(manifest->find(3)->outcome, LineManifestEntry::Outcome::Saved);
    QCOMPARE(progressDevices, (QList<int>{1, 3}));
    // The manifest on disk says the same, and its hashes are the files'.
    const Result<LineManifest> onDisk =
        loadLineManifest(QDir(line.dir.path()).filePath(QLatin1String(kLineManifestName)));
    QVERIFY(onDisk.ok());
    QCOMPARE(onDisk->devices.size(), 3);
    const Result<QByteArray> bytes = readFileBytes(QDir(line.dir.path()).filePath(one->file));
    QCOMPARE(sha256Hex(*bytes), one->sha256);
    QCOMPARE(onDisk->line, QString());
}

void TestBackup::verifyLineComparesEverySavedDevice() {
    Line line;
    QVERIFY(line.backup().ok());
    const Result<QList<LineVerifyEntry>> entries = verifyLine(*line.bench.client, line.dir.path());
    QVERIFY2(entries.ok(), qPrintable(entries.error().message));
    QCOMPARE(entries->size(), 3);
    QVERIFY(entries->at(0).equal);
    QVERIFY(!entries->at(1).equal);
    QVERIFY(entries->at(1).text.contains(QLatin1String("not verified")));
    QVERIFY(entries->at(2).equal);
    // A change on device 3 shows.
    line.bench.client->setDevice(3);
    QVERIFY(line.bench.client->writeTrack(0, Track{5, {{1, 2}}}).ok());
    const Result<QList<LineVerifyEntry>> again = verifyLine(*line.bench.client, line.dir.path());
    QVERIFY(!again->at(2).equal);
    QVERIFY2(again->at(2).text.contains(QLatin1String("differs")), qPrintable(again->at(2).text));
}

void TestBackup::resumeSkipsDevicesAlreadySaved() {
    Line line;
    QVERIFY(line.backup().ok());
    // Device 2 answers again; the resumed run reads only it.
    line.bench.injections().setDead(2, false);
    line.bench.injections().clearLog();
    const Result<LineManifest> resumed = line.backup(true);
    QVERIFY2(resumed.ok(), qPrintable(resumed.error().message));
    QVERIFY(resumed->allSaved());
    for (const SimInjections::Received& received : line.bench.injections().received())
        QCOMPARE(received.device, 2);
    QVERIFY(line.bench.injections().count('?', "EE") > 0);
}

void TestBackup::resumeDoesNotTrustAChangedImage() {
    Line line;
    line.bench.injections().setDead(2, false);
    QVERIFY(line.backup().ok());
    const QString file =
        QDir(line.dir.path()).filePath(QStringLiteral("device-03_11.10.1994_32out.json"));
    QByteArray bytes = *readFileBytes(file);
    bytes.append(' ');
    QVERIFY(writeFileBytes(file, bytes));
    line.bench.injections().clearLog();
    QVERIFY(line.backup(true).ok());
    for (const SimInjections::Received& received : line.bench.injections().received())
        QCOMPARE(received.device, 3);
    QVERIFY(line.bench.injections().count('?', "EE") > 0);
}

QTEST_GUILESS_MAIN(TestBackup)
#include "tst_backup.moc"
