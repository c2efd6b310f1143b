// Issue 30, item 3 (status): `cambench-cli machine status FILE` against two
// real simulators of different families on pseudo-terminals (a CamCon of
// another firmware with 16 outputs, a Compax3 S150V4) and a port where
// nothing is: one line per device, each with its own identity, and exit 3
// naming the device that was not reached. A wrong family in the file is
// refused before any device is asked, naming the device.
#include "e2e_support.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace cambench::e2e;

namespace {

// JSON written with ' for " (readable here; moc skips a file with raw strings).
QByteArray json(const char* text) {
    return QByteArray(text).replace('\'', '"');
}

QByteArray machineFile(const QString& camcon, const QString& drive, const QString& driveFamily) {
    return QString::fromUtf8(
               json("{'machine': 'Press 7', 'devices': ["
                    "        {'name': 'cams', 'family': 'camcon', 'port': '%1', 'baud': 115200},"
                    "        {'name': 'feed', 'family': '%3', 'port': '%2', 'baud': 115200},"
                    "        {'name': 'spare', 'family': 'camcon', 'port': "
                    "'/dev/cambench-no-such-port'}]}"))
        .arg(camcon, drive, driveFamily)
        .toUtf8();
}

}  // namespace

class TestE2eMachine : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void statusNamesEachDevicesIdentity() {
        SimSession cams;
        START_SIM(cams, {"--eprom", "03.05.2001", "--outputs", "16"});
        SimSession feed(QStringLiteral("compax3"));
        START_SIM(feed, {"--drive-type", "S150V4"});
        const QString file = cams.path(QStringLiteral("press7.json"));
        QVERIFY(writeBytes(file, machineFile(cams.ptyPath(), feed.ptyPath(), "compax3")));

        const CliRun run = runCli({"machine", "status", file});
        VERIFY_EXIT(run, 3);  // the spare was not reached
        const QStringList lines = run.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 4);
        QCOMPARE(lines.at(0), QStringLiteral("Press 7"));
        QVERIFY2(lines.at(1).startsWith(QStringLiteral("cams\tcamcon\t")) &&
                     lines.at(1).contains(QLatin1String("EPROM 03.05.2001")) &&
                     lines.at(1).contains(QLatin1String("16 outputs")),
                 qPrintable(lines.at(1)));
        QVERIFY2(lines.at(2).startsWith(QStringLiteral("feed\tcompax3\t")) &&
                     lines.at(2).contains(QLatin1String("S150V4")),
                 qPrintable(lines.at(2)));
        QVERIFY2(lines.at(3).startsWith(QStringLiteral("spare\tcamcon\t")) &&
                     lines.at(3).contains(QLatin1String("NOT REACHED")),
                 qPrintable(lines.at(3)));

        const CliRun json = runCli({"machine", "status", file, "--json"});
        VERIFY_EXIT(json, 3);
        const QJsonArray devices =
            QJsonDocument::fromJson(json.out.toUtf8()).object().value("devices").toArray();
        QCOMPARE(devices.size(), 3);
        QVERIFY(devices.at(0).toObject().contains(QStringLiteral("identity")));
        QVERIFY(devices.at(2).toObject().contains(QStringLiteral("error")));
    }

    // Backup, a change on one device, verify names it, restore of that one,
    // verify equal; then another CamCon behind the port: its restore is
    // refused naming the device, and nothing is written to it.
    void backupVerifyRestoreByEachFamilysOwnCommands() {
        SimSession cams;
        START_SIM(cams, {"--eprom", "03.05.2001", "--outputs", "16"});
        SimSession feed(QStringLiteral("compax3"));
        START_SIM(feed, {"--drive-type", "S150V4"});
        const QByteArray machine = machineFile(cams.ptyPath(), feed.ptyPath(), "compax3");
        const QString file = cams.path(QStringLiteral("press7.json"));
        // Without the spare: every device must answer for exit 0.
        const QJsonObject root = QJsonDocument::fromJson(machine).object();
        QJsonArray devices = root.value("devices").toArray();
        devices.removeLast();
        QJsonObject two = root;
        two.insert(QStringLiteral("devices"), devices);
        QVERIFY(writeBytes(file, QJsonDocument(two).toJson()));
        const QString dir = cams.path(QStringLiteral("press7-backup"));

        const CliRun backup = runCli({"machine", "backup", file, "-o", dir});
        VERIFY_EXIT(backup, 0);
        QVERIFY2(backup.out.contains(QLatin1String("2 of 2 devices saved")),
                 qPrintable(backup.out));
        const QJsonObject manifest =
            QJsonDocument::fromJson(readBytes(dir + QStringLiteral("/manifest.json"))).object();
        const QJsonArray saved = manifest.value("devices").toArray();
        QCOMPARE(saved.size(), 2);
        // What tells the CamCon apart, to compare, and what it said of itself.
        QCOMPARE(saved.at(0).toObject().value("identity").toObject().value("eprom").toString(),
                 QStringLiteral("03.05.2001"));
        QVERIFY(saved.at(0).toObject().value("device").toString().contains("03.05.2001"));
        QCOMPARE(saved.at(1).toObject().value("sha256").toString().size(), 64);
        VERIFY_EXIT(runCli({"machine", "verify", dir}), 0);

        // The CamCon's program 0 changes at its panel: verify names it.
        const QString one = cams.path(QStringLiteral("one.csv"));
        QVERIFY(writeBytes(one, "output,cam,on,off\n1,1,100,120\n"));
        VERIFY_EXIT(cams.cli({"cams", "write", "--program", "0", one}), 0);
        const CliRun differs = runCli({"machine", "verify", dir});
        VERIFY_EXIT(differs, 1);
        QVERIFY2(differs.out.contains(QLatin1String("cams: DIFFERS (3)\nfeed: equal")),
                 qPrintable(differs.out));

        const CliRun restore = runCli({"machine", "restore", dir, "--only", "cams"});
        VERIFY_EXIT(restore, 0);
        QVERIFY2(restore.out.contains(QLatin1String("cams: restored")), qPrintable(restore.out));
        QVERIFY(!restore.out.contains(QLatin1String("feed:")));
        VERIFY_EXIT(runCli({"machine", "verify", dir}), 0);

        // Another CamCon where the cams were: refused, named, left alone.
        SimSession other;
        START_SIM(other, {"--eprom", "11.10.1994"});
        QByteArray moved = readBytes(dir + QStringLiteral("/machine.json"));
        moved.replace(cams.ptyPath().toUtf8(), other.ptyPath().toUtf8());
        QVERIFY(writeBytes(dir + QStringLiteral("/machine.json"), moved));
        const CliRun refused = runCli({"machine", "restore", dir, "--only", "cams"});
        VERIFY_EXIT(refused, 4);
        QVERIFY2(refused.out.contains(QLatin1String("cams: ANOTHER DEVICE: another device "
                                                    "answers: expected ")) &&
                     refused.out.contains(QLatin1String("eprom 03.05.2001")) &&
                     refused.out.contains(QLatin1String("eprom 11.10.1994")),
                 describe(refused).constData());
        VERIFY_EXIT(other.cli({"verify", dir + QStringLiteral("/cams.json")}), 1);
    }

    void aWrongFamilyIsRefusedBeforeAnyDeviceIsAsked() {
        SimSession cams;
        START_SIM(cams);
        const QString file = cams.path(QStringLiteral("press7.json"));
        QVERIFY(writeBytes(file, machineFile(cams.ptyPath(), cams.ptyPath(), "compax")));
        const CliRun run = runCli({"machine", "status", file});
        VERIFY_EXIT(run, 4);
        QVERIFY2(run.err.contains(QLatin1String("device feed")) &&
                     run.err.contains(QLatin1String("\"compax\"")),
                 qPrintable(run.err));
        QVERIFY(run.out.isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestE2eMachine)
#include "tst_e2e_machine.moc"
