// The manifest of a line backup.
#include "model/camcon/line_manifest.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace cambench;

namespace {

LineManifest sample() {
    LineManifest manifest;
    manifest.line = QStringLiteral("/dev/ttyUSB0, multiuser, 38400 baud");
    LineManifestEntry saved;
    saved.device = 5;
    saved.identity = DeviceInfo();
    saved.identity->deviceNumber = 5;
    saved.file = QStringLiteral("device-05_11.10.1994_32out.json");
    saved.sha256 = sha256Hex("image");
    saved.time = QDateTime(QDate(2026, 5, 4), QTime(3, 2, 1), Qt::UTC);
    saved.outcome = LineManifestEntry::Outcome::Saved;
    LineManifestEntry failed;
    failed.device = 2;
    failed.time = saved.time;
    failed.message = QStringLiteral("no answer; check the cable");
    manifest.put(saved);
    manifest.put(failed);
    return manifest;
}

}  // namespace

class TestLineManifest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void entriesAreKeptInDeviceOrder() {
        const LineManifest manifest = sample();
        QCOMPARE(manifest.devices.at(0).device, 2);
        QCOMPARE(manifest.devices.at(1).device, 5);
        QVERIFY(!manifest.allSaved());
    }

    void roundTrip() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QLatin1String(kLineManifestName));
        QVERIFY(saveLineManifest(path, sample()).ok());
        const Result<LineManifest> loaded = loadLineManifest(path);
        QVERIFY2(loaded.ok(), qPrintable(loaded.error().message));
        QCOMPARE(loaded->line, sample().line);
        QCOMPARE(loaded->devices.size(), 2);
        const LineManifestEntry* five = loaded->find(5);
        QCOMPARE(five->file, QStringLiteral("device-05_11.10.1994_32out.json"));
        QCOMPARE(five->sha256, sha256Hex("image"));
        QCOMPARE(five->time, sample().find(5)->time);
        QCOMPARE(five->identity->deviceNumber, 5);
        QCOMPARE(loaded->find(2)->outcome, LineManifestEntry::Outcome::Failed);
        QVERIFY(!loaded->find(2)->identity);
        QVERIFY(lineManifestToJson(*loaded).contains("\"result\": \"failed\""));
    }

    void sha256IsLowerCaseHex() {
        QCOMPARE(
            sha256Hex("abc"),
            QStringLiteral("ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"));
    }

    void damagedManifestIsRefused() {
        QByteArray bytes = lineManifestToJson(sample());
        bytes.replace("\"saved\"", "\"maybe\"");
        const Result<LineManifest> loaded = lineManifestFromJson(bytes);
        QVERIFY(!loaded.ok());
        QVERIFY2(loaded.error().message.contains(QLatin1String("\"maybe\"")),
                 qPrintable(loaded.error().message));
    }
};

QTEST_GUILESS_MAIN(TestLineManifest)
#include "tst_line_manifest.moc"
