// backup / verify / restore with the real executables, and the restore's
// refusal of damaged, truncated and foreign images.
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
    QVERIFY2(differs.out.contains(QLatin1String("differs")), qPrintable(differs.out));

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
        const QByteArray key = "\"data\": \"";
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

QTEST_GUILESS_MAIN(TestE2eEeprom)
#include "tst_e2e_eeprom.moc"
