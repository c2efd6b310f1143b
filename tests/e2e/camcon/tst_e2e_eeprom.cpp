// backup / verify / restore with the real executables, and the restore's
// refusal of damaged, truncated and foreign images. Issue 36: a backup holds
// its blocks and the same content decoded (verify and diff name cams, not
// blocks), and a backup of the older format (the blocks alone) restores
// byte for byte as the new one does.
#include "../e2e_support.h"

#include "model/camcon/eeprom_image_file.h"

#include <QDir>
#include <QTest>

using namespace cambench;
using namespace cambench::e2e;

namespace {

// Makes the device differ from its backup: one more cam on output 9.
void changeDevice(const SimSession& session) {
    const QString csv = session.path(QStringLiteral("change.csv"));
    QVERIFY(writeBytes(csv, "output,cam,on,off\n9,1,200,220\n"));
    VERIFY_EXIT(session.cli({"cams", "write", "--program", "2", csv}), 0);
}

}  // namespace

class TestE2eEeprom : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void backupChangeRestoreVerify();
    void restoreRefusesDamagedImagesWithoutTouchingTheDevice_data();
    void restoreRefusesDamagedImagesWithoutTouchingTheDevice();
    void restoreOfOtherDeviceNeedsForce();
    void oldAndNewFormatRestoreByteForByte();
    void diffTakesBackups();
};

void TestE2eEeprom::backupChangeRestoreVerify() {
    SimSession session;
    START_SIM(session);
    const QString image = session.path(QStringLiteral("image.json"));
    VERIFY_EXIT(session.cli({"backup", "-o", image}), 0);
    VERIFY_EXIT(session.cli({"verify", image}), 0);

    changeDevice(session);
    const CliRun differs = session.cli({"verify", image});
    VERIFY_EXIT(differs, 1);
    // Named in the content's terms, not as blocks.
    QVERIFY2(differs.out.contains(QStringLiteral("program 2, output 9: cam 200–220 added")),
             qPrintable(differs.out));

    const CliRun restore = session.cli({"restore", image});
    VERIFY_EXIT(restore, 0);
    // The safety backup lies next to the image and holds the changed device.
    const QStringList safety =
        QDir(session.path(QString())).entryList({QStringLiteral("image.json.safety-*.json")});
    QCOMPARE(safety.size(), 1);
    QVERIFY(restore.err.contains(safety.first()));
    VERIFY_EXIT(session.cli({"verify", image}), 0);
    VERIFY_EXIT(session.cli({"verify", session.path(safety.first())}), 1);

    const CliRun cams = session.cli({"cams", "read", "--program", "2", "--output", "9"});
    QCOMPARE(cams.out, QStringLiteral("output,cam,on,off\n"));
}

void TestE2eEeprom::restoreRefusesDamagedImagesWithoutTouchingTheDevice_data() {
    QTest::addColumn<QString>("damage");
    QTest::newRow("tampered block") << "tampered";
    QTest::newRow("truncated file") << "truncated";
    QTest::newRow("project file") << "project";
    QTest::newRow("random bytes") << "random";
}

void TestE2eEeprom::restoreRefusesDamagedImagesWithoutTouchingTheDevice() {
    QFETCH(QString, damage);
    SimSession session;
    START_SIM(session);
    const QString good = session.path(QStringLiteral("good.json"));
    VERIFY_EXIT(session.cli({"backup", "-o", good}), 0);
    const QByteArray bytes = readBytes(good);
    QByteArray bad;
    if (damage == QLatin1String("tampered")) {
        // One hex digit of the second block changed; the hash no longer matches.
        bad = bytes;
        const QByteArray key = "\"data\":\"";
        const qsizetype second = bad.indexOf(key, bad.indexOf(key) + 1);
        QVERIFY(second > 0);
        const qsizetype digit = second + key.size() + 4;
        bad[digit] = bad[digit] == '0' ? '1' : '0';
    } else if (damage == QLatin1String("truncated")) {
        bad = bytes.left(bytes.size() / 2);
    } else if (damage == QLatin1String("project")) {
        bad = R"({"format":"cambench-project","version":1,"programs":[]})";
    } else {
        for (int i = 0; i < 4096; ++i) bad.append(char((i * 7919 + 13) & 0xFF));
    }
    QVERIFY(bad != bytes);
    const QString badPath = session.path(QStringLiteral("bad.json"));
    QVERIFY(writeBytes(badPath, bad));
    const CliRun run = session.cli({"restore", "--no-safety-backup", badPath});
    VERIFY_EXIT(run, 4);
    QVERIFY(run.err.startsWith(QLatin1String("cambench-cli: ")));
    QCOMPARE(run.err.count(u'\n'), 1);
    // The device still equals the backup taken before.
    VERIFY_EXIT(session.cli({"verify", good}), 0);
}

void TestE2eEeprom::restoreOfOtherDeviceNeedsForce() {
    SimSession session;
    START_SIM(session);
    const QString path = session.path(QStringLiteral("image.json"));
    VERIFY_EXIT(session.cli({"backup", "-o", path}), 0);
    Result<EepromImage> image = eepromImageFromJson(readBytes(path));
    QVERIFY2(image.ok(), qPrintable(image.error().message));
    image.value().device.outputs = 64;  // taken from a bigger device
    const QString foreign = session.path(QStringLiteral("foreign.json"));
    QVERIFY(writeBytes(foreign, eepromImageToJson(*image)));
    changeDevice(session);
    const QString changed = session.path(QStringLiteral("changed.json"));
    VERIFY_EXIT(session.cli({"backup", "-o", changed}), 0);

    const CliRun refused = session.cli({"restore", foreign});
    VERIFY_EXIT(refused, 4);
    QVERIFY2(refused.err.contains(QLatin1String("another device answers: expected outputs 64")),
             qPrintable(refused.err));
    QVERIFY2(refused.err.contains(QLatin1String("--replacement")), qPrintable(refused.err));
    VERIFY_EXIT(session.cli({"verify", changed}), 0);  // untouched

    // --force: the older name of --replacement.
    VERIFY_EXIT(session.cli({"restore", "--force", "--no-safety-backup", foreign}), 0);
    VERIFY_EXIT(session.cli({"verify", path}), 0);
}

// The older format's file (tests/e2e/camcon/data/eeprom-image-v1.json:
// CamBench 0.1.0 before issue 36, a device of EPROM 03.05.2001 with 16
// outputs and two cams on output 9 of program 2, 200–220 and 300–310) goes
// to a device without them; a new backup of it holds the very same blocks
// and the content decoded; that backup restored over a changed device
// gives the same blocks again.
void TestE2eEeprom::oldAndNewFormatRestoreByteForByte() {
    SimSession session;
    START_SIM(session, {"--eprom", "03.05.2001", "--outputs", "16"});
    const QString old = session.path(QStringLiteral("old.json"));
    const QByteArray oldBytes = readBytes(QStringLiteral(CAMBENCH_E2E_CAMCON_DATA) +
                                          QStringLiteral("/eeprom-image-v1.json"));
    QVERIFY(oldBytes.contains("\"version\": 1"));
    QVERIFY(writeBytes(old, oldBytes));
    const Result<EepromImage> oldImage = loadEepromImage(old);
    QVERIFY2(oldImage.ok(), qPrintable(oldImage.error().message));
    QVERIFY(oldImage->content.isEmpty());
    const CliRun before = session.cli({"verify", old});
    VERIFY_EXIT(before, 1);  // the device lacks output 9's cams
    QVERIFY2(before.out.contains(QLatin1String("older format")), qPrintable(before.out));

    VERIFY_EXIT(session.cli({"restore", old}), 0);
    VERIFY_EXIT(session.cli({"verify", old}), 0);
    QCOMPARE(session.cli({"cams", "read", "--program", "2", "--output", "9"}).out,
             QStringLiteral("output,cam,on,off\n9,1,200,220\n9,2,300,310\n"));
    const QString fresh = session.path(QStringLiteral("new.json"));
    VERIFY_EXIT(session.cli({"backup", "-o", fresh}), 0);
    const Result<EepromImage> newImage = loadEepromImage(fresh);
    QVERIFY2(newImage.ok(), qPrintable(newImage.error().message));
    QVERIFY(newImage->blocks == oldImage->blocks);
    QVERIFY(readBytes(fresh).contains("\"version\": 2"));
    // The content, one item a line: output 9's track of program 2.
    QVERIFY2(readBytes(fresh).contains("{\"cams\":[[200,220],[300,310]],\"output\":9}"),
             readBytes(fresh).constData());

    changeDevice(session);  // output 9 of program 2: 200–220 alone
    const CliRun differs = session.cli({"verify", fresh});
    VERIFY_EXIT(differs, 1);
    QVERIFY2(differs.out.contains(QStringLiteral("program 2, output 9: cam 300–310 removed")),
             qPrintable(differs.out));
    VERIFY_EXIT(session.cli({"restore", fresh}), 0);
    const QString again = session.path(QStringLiteral("again.json"));
    VERIFY_EXIT(session.cli({"backup", "-o", again}), 0);
    const Result<EepromImage> againImage = loadEepromImage(again);
    QVERIFY2(againImage.ok(), qPrintable(againImage.error().message));
    QVERIFY(againImage->blocks == oldImage->blocks);
}

// `diff` takes two CamCon backups as it takes project files: their decoded
// programs; a backup of the older format is refused, saying why.
void TestE2eEeprom::diffTakesBackups() {
    SimSession session;
    START_SIM(session);
    const QString first = session.path(QStringLiteral("first.json"));
    VERIFY_EXIT(session.cli({"backup", "-o", first}), 0);
    changeDevice(session);
    const QString second = session.path(QStringLiteral("second.json"));
    VERIFY_EXIT(session.cli({"backup", "-o", second}), 0);
    const CliRun diff = runCli({"diff", first, second});
    VERIFY_EXIT(diff, 1);
    QVERIFY2(
        diff.out.contains(QLatin1String("output 9")) && diff.out.contains(QLatin1String("200")),
        qPrintable(diff.out));
    VERIFY_EXIT(runCli({"diff", first, first}), 0);
    const QString old = session.path(QStringLiteral("old.json"));
    QVERIFY(writeBytes(old, readBytes(QStringLiteral(CAMBENCH_E2E_CAMCON_DATA) +
                                      QStringLiteral("/eeprom-image-v1.json"))));
    const CliRun refused = runCli({"diff", old, second});
    VERIFY_EXIT(refused, 4);
    QVERIFY2(refused.err.contains(QLatin1String("older format")), qPrintable(refused.err));
}

QTEST_GUILESS_MAIN(TestE2eEeprom)
#include "tst_e2e_eeprom.moc"
