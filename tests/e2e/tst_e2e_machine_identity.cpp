// Issue 35, item 8 and issue 36, item 6: a restore goes only to the device
// it was taken from. Two Compax3 drives that differ only in their serial
// number and two MC200 V2s that differ only in their PLC program (where its
// data block starts, SYSDATA 08) hold other values; two CamCons differ in
// their firmware (EPROM date). Each is a real cambench-sim on its own pty
// logging every request it receives (--verbose). After
// `machine backup` (which records each identity in the machine file) the
// two ports of each pair are swapped in the machine file, as when the
// cables were changed over: `machine status` and `machine verify` say
// "another device" for each, naming both identities; `machine restore`
// writes nothing (not one write request reaches any simulator) and exits
// 4; `--replacement NAME` lets exactly that device through. A single
// device's restore to the other drive refuses the same way, and a backup
// older than the identity record is refused unless the person confirms.
#include "e2e_support.h"

#include "model/json_file.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace cambench::e2e;

namespace {

QJsonObject deviceAt(const QString& name, const QString& family, const QString& port) {
    QJsonObject device{{"name", name}, {"family", family}, {"port", port}, {"baud", 115200}};
    if (family == QLatin1String("mc1")) {
        device.insert("protocol", "mc1");
        device.insert("variant", "mc200v2");
    }
    return device;
}

QJsonObject readJson(const QString& path) {
    return QJsonDocument::fromJson(readBytes(path)).object();
}

// The machine file with the ports of `a` and `b` exchanged (and all else,
// the recorded identities too, kept).
QByteArray swapPorts(const QJsonObject& machine, const QString& a, const QString& b) {
    QJsonArray devices = machine.value("devices").toArray();
    int ia = -1;
    int ib = -1;
    for (int i = 0; i < devices.size(); ++i) {
        const QString name = devices.at(i).toObject().value("name").toString();
        if (name == a) ia = i;
        if (name == b) ib = i;
    }
    if (ia < 0 || ib < 0) return {};
    QJsonObject da = devices.at(ia).toObject();
    QJsonObject db = devices.at(ib).toObject();
    const QJsonValue port = da.value("port");
    da.insert("port", db.value("port"));
    db.insert("port", port);
    devices[ia] = da;
    devices[ib] = db;
    QJsonObject swapped = machine;
    swapped.insert("devices", devices);
    return QJsonDocument(swapped).toJson();
}

// The requests a simulator logged (--verbose: "<- ..." one each).
QStringList requests(const SimSession& session) {
    QStringList found;
    for (const QString& line :
         QString::fromUtf8(readBytes(session.path(QStringLiteral("sim-stderr.log"))))
             .split(QLatin1Char('\n')))
        if (const qsizetype at = line.indexOf(QLatin1String("<- ")); at >= 0)
            found << line.mid(at + 3).trimmed();
    return found;
}

// Compax3 writes: "O1901,1=100" (a read has no '=').
int compax3Writes(const SimSession& drive) {
    int writes = 0;
    for (const QString& request : requests(drive))
        if (request.contains(QLatin1Char('='))) ++writes;
    return writes;
}

// CamCon commands ('!'): "! EE 12 bytes" (a query is '?').
int camconWrites(const SimSession& cams) {
    int writes = 0;
    for (const QString& request : requests(cams))
        if (request.startsWith(QLatin1Char('!'))) ++writes;
    return writes;
}

// MC-1 telegrams that write or act: everything but the reads (RDVAR,
// RDBYTE, RDBLOCK/RDMEM6, RDSTAT, RDTABLE, RDMEM, RDBIT) and the SYSDATA
// reads (status 00, UDB address 08).
int mc1Writes(const SimSession& controller) {
    static const QList<int> reads{0xC3, 0x22, 0xA3, 0xD5, 0xE3, 0xE5, 0xD6, 0x33, 0xB4};
    int writes = 0;
    for (const QString& request : requests(controller)) {
        const QByteArray telegram = QByteArray::fromHex(request.toLatin1());
        if (telegram.isEmpty()) continue;
        const int op = quint8(telegram.at(0));
        if (reads.contains(op)) continue;
        if (op == 0x92 && telegram.size() >= 3 &&
            (quint8(telegram.at(2)) == 0x00 || quint8(telegram.at(2)) == 0x08))
            continue;
        ++writes;
    }
    return writes;
}

}  // namespace

// Two drives that differ only in their serial number, two MC200 V2s that
// differ only in their PLC program's data block, each holding its own
// values (four writes, counted by the simulators), and two CamCons of
// other firmware (EPROM date).
struct Machine {
    SimSession camsA;
    SimSession camsB;
    SimSession feedA{QStringLiteral("compax3")};
    SimSession feedB{QStringLiteral("compax3")};
    SimSession plcA{QStringLiteral("mc1")};
    SimSession plcB{QStringLiteral("mc1")};

    void start() {
        START_SIM(feedA, {"--serial", "C3-1001", "--verbose"});
        START_SIM(feedB, {"--serial", "C3-2002", "--verbose"});
        START_SIM(plcA, {"--variant", "mc200v2", "--udb", "0x10000", "--verbose"});
        START_SIM(plcB, {"--variant", "mc200v2", "--udb", "0x14000", "--verbose"});
        START_SIM(camsA, {"--eprom", "03.05.2001", "--outputs", "32", "--verbose"});
        START_SIM(camsB, {"--eprom", "11.10.1994", "--outputs", "32", "--verbose"});
        VERIFY_EXIT(feedA.cli({"c3", "write", "1901.1=100"}), 0);
        VERIFY_EXIT(feedB.cli({"c3", "write", "1901.1=200"}), 0);
        VERIFY_EXIT(plcA.cli({"mc", "var", "write", "12", "111"}), 0);
        VERIFY_EXIT(plcB.cli({"mc", "var", "write", "12", "222"}), 0);
    }

    QByteArray file() const {
        const QJsonArray devices{deviceAt("feed-x", "compax3", feedA.ptyPath()),
                                 deviceAt("feed-y", "compax3", feedB.ptyPath()),
                                 deviceAt("plc-x", "mc1", plcA.ptyPath()),
                                 deviceAt("plc-y", "mc1", plcB.ptyPath()),
                                 deviceAt("cams-x", "camcon", camsA.ptyPath()),
                                 deviceAt("cams-y", "camcon", camsB.ptyPath())};
        return QJsonDocument(QJsonObject{{"machine", "Press 9"}, {"devices", devices}}).toJson();
    }

    int writes() const {
        return compax3Writes(feedA) + compax3Writes(feedB) + mc1Writes(plcA) + mc1Writes(plcB) +
               camconWrites(camsA) + camconWrites(camsB);
    }
};

class TestE2eMachineIdentity : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void swappedPortsWriteNothing() {
        Machine m;
        m.start();
        if (QTest::currentTestFailed()) return;
        const QString file = m.feedA.path(QStringLiteral("press9.json"));
        QVERIFY(writeBytes(file, m.file()));
        const QString dir = m.feedA.path(QStringLiteral("press9-backup"));
        const CliRun backup = runCli({"machine", "backup", file, "-o", dir});
        VERIFY_EXIT(backup, 0);
        // The backup records what tells each device apart: in the manifest,
        // the backup's machine file and the person's machine file.
        QVERIFY2(backup.out.contains(QLatin1String("records the identity of feed-x, feed-y, "
                                                   "plc-x, plc-y, cams-x, cams-y")),
                 qPrintable(backup.out));
        const QJsonObject recorded = readJson(file);
        const QJsonObject feedX = recorded.value("devices").toArray().at(0).toObject();
        QCOMPARE(feedX.value("identity").toObject().value("serial").toString(),
                 QStringLiteral("C3-1001"));
        const QJsonObject plcY = recorded.value("devices").toArray().at(3).toObject();
        QCOMPARE(plcY.value("identity").toObject().value("program udb").toString(),
                 QStringLiteral("0x00014000"));
        QCOMPARE(readJson(dir + QStringLiteral("/machine.json")), recorded);
        const QJsonArray manifest =
            readJson(dir + QStringLiteral("/manifest.json")).value("devices").toArray();
        QCOMPARE(manifest.at(1).toObject().value("identity").toObject().value("serial").toString(),
                 QStringLiteral("C3-2002"));
        VERIFY_EXIT(runCli({"machine", "status", file}), 0);
        QCOMPARE(m.writes(), 4);  // the four values written above, nothing since

        // The cables are changed over: each pair's ports swapped.
        QVERIFY(writeBytes(file, swapPorts(readJson(file), "feed-x", "feed-y")));
        QVERIFY(writeBytes(file, swapPorts(readJson(file), "plc-x", "plc-y")));
        QVERIFY(writeBytes(file, swapPorts(readJson(file), "cams-x", "cams-y")));
        // The backup's own machine file too: restore and verify reach each
        // device through the ports it records.
        const QString folderFile = dir + QStringLiteral("/machine.json");
        QVERIFY(writeBytes(folderFile, swapPorts(readJson(folderFile), "feed-x", "feed-y")));
        QVERIFY(writeBytes(folderFile, swapPorts(readJson(folderFile), "plc-x", "plc-y")));
        QVERIFY(writeBytes(folderFile, swapPorts(readJson(folderFile), "cams-x", "cams-y")));

        const CliRun status = runCli({"machine", "status", file});
        VERIFY_EXIT(status, 4);
        QVERIFY2(status.out.contains(QLatin1String("feed-x\tcompax3\t")), qPrintable(status.out));
        QVERIFY2(status.out.contains(QLatin1String("\tANOTHER DEVICE: another device answers: "
                                                   "expected serial C3-1001, found serial "
                                                   "C3-2002")),
                 qPrintable(status.out));
        QVERIFY2(status.out.contains(QLatin1String("expected program udb 0x00014000, found "
                                                   "program udb 0x00010000")),
                 qPrintable(status.out));

        const CliRun verify = runCli({"machine", "verify", dir});
        VERIFY_EXIT(verify, 4);
        QVERIFY2(verify.out.contains(QLatin1String("feed-y: ANOTHER DEVICE: another device "
                                                   "answers: expected serial C3-2002, found "
                                                   "serial C3-1001")),
                 qPrintable(verify.out));

        const CliRun restore = runCli({"machine", "restore", dir});
        VERIFY_EXIT(restore, 4);
        for (const char* name : {"feed-x", "feed-y", "plc-x", "plc-y", "cams-x", "cams-y"})
            QVERIFY2(
                restore.out.contains(QLatin1String(name) + QLatin1String(": ANOTHER DEVICE: ")),
                describe(restore).constData());
        QVERIFY2(restore.err.contains(QLatin1String("Nothing was written to it. Only if it "
                                                    "replaces that device, add --replacement "
                                                    "plc-x.")),
                 qPrintable(restore.err));
        QCOMPARE(m.writes(), 4);  // not one write telegram on any wire

        // A backup of the swapped machine saves nothing from another device.
        const CliRun again = runCli({"machine", "backup", file, "-o", dir + QStringLiteral("2")});
        VERIFY_EXIT(again, 3);
        QVERIFY2(again.out.contains(QLatin1String("0 of 6 devices saved")), qPrintable(again.out));

        // The person says drive B replaces drive A: its backup goes there,
        // and only there.
        const CliRun replaced = runCli({"machine", "restore", dir, "--replacement", "feed-x"});
        VERIFY_EXIT(replaced, 4);
        QVERIFY2(replaced.out.contains(QLatin1String("feed-x: restored\nfeed-y: ANOTHER DEVICE")),
                 qPrintable(replaced.out));
        QCOMPARE(compax3Writes(m.feedA), 1);
        QVERIFY(compax3Writes(m.feedB) > 1);
        QCOMPARE(mc1Writes(m.plcA) + mc1Writes(m.plcB), 2);
        QCOMPARE(camconWrites(m.camsA) + camconWrites(m.camsB), 0);
        const CliRun value = m.feedB.cli({"c3", "read", "1901.1"});
        VERIFY_EXIT(value, 0);
        QVERIFY2(value.out.contains(QLatin1String("100")), qPrintable(value.out));
    }

    void singleRestoreGoesOnlyToItsDevice() {
        Machine m;
        m.start();
        if (QTest::currentTestFailed()) return;
        const QString file = m.feedA.path(QStringLiteral("feed-a.json"));
        VERIFY_EXIT(m.feedA.cli({"c3", "backup", "-o", file}), 0);
        const CliRun refused = m.feedB.cli({"c3", "restore", file});
        VERIFY_EXIT(refused, 4);
        QVERIFY2(refused.err.contains(QLatin1String("another device answers: expected serial "
                                                    "C3-1001, found serial C3-2002")),
                 qPrintable(refused.err));
        QVERIFY2(refused.err.contains(QLatin1String("Nothing was written")),
                 qPrintable(refused.err));
        QCOMPARE(compax3Writes(m.feedB), 1);  // its own value, written above
        VERIFY_EXIT(m.feedB.cli({"c3", "restore", file, "--replacement"}), 0);
        QVERIFY(compax3Writes(m.feedB) > 1);

        const QString program = m.plcA.path(QStringLiteral("plc-a.json"));
        VERIFY_EXIT(m.plcA.cli({"mc", "backup", "-o", program, "--vars", "10-14", "--no-flags"}),
                    0);
        const CliRun other = m.plcB.cli({"mc", "restore", program});
        VERIFY_EXIT(other, 4);
        QVERIFY2(other.err.contains(QLatin1String("expected program udb 0x00010000, found "
                                                  "program udb 0x00014000")),
                 qPrintable(other.err));
        QCOMPARE(mc1Writes(m.plcB), 1);
        VERIFY_EXIT(m.plcB.cli({"mc", "restore", program, "--replacement"}), 0);
        QCOMPARE(mc1Writes(m.plcB), 2);  // V12: 222 -> 111

        const QString image = m.camsA.path(QStringLiteral("cams-a.json"));
        VERIFY_EXIT(m.camsA.cli({"backup", "-o", image}), 0);
        const CliRun cams = m.camsB.cli({"restore", image});
        VERIFY_EXIT(cams, 4);
        QVERIFY2(cams.err.contains(QLatin1String("another device answers: expected ")) &&
                     cams.err.contains(QLatin1String("eprom 03.05.2001")) &&
                     cams.err.contains(QLatin1String("eprom 11.10.1994")),
                 qPrintable(cams.err));
        QCOMPARE(camconWrites(m.camsB), 0);  // refused before the safety backup and the erase
        VERIFY_EXIT(m.camsB.cli({"restore", image, "--replacement", "--no-safety-backup"}), 0);
        QVERIFY(camconWrites(m.camsB) > 0);
    }

    void olderBackupWithoutIdentityNeedsConfirmation() {
        // An MC-1 backup made before the identity record: it cannot be told
        // whether the controller answering is its own, so it is refused
        // until the person confirms (--replacement).
        Machine m;
        START_SIM(m.plcA, {"--variant", "mc200v2", "--verbose"});
        const QString path = m.plcA.path(QStringLiteral("old.json"));
        VERIFY_EXIT(m.plcA.cli({"mc", "backup", "-o", path, "--vars", "10-14", "--no-flags"}), 0);
        QJsonObject old = readJson(path);
        QVERIFY(old.contains("identity"));
        old.remove("identity");
        old.remove("sha256");
        cambench::sealWithHash(old);
        QVERIFY(writeBytes(path, QJsonDocument(old).toJson()));
        VERIFY_EXIT(m.plcA.cli({"mc", "var", "write", "12", "5"}), 0);
        const CliRun refused = m.plcA.cli({"mc", "restore", path});
        VERIFY_EXIT(refused, 4);
        QVERIFY2(refused.err.contains(QLatin1String("records no identity")),
                 qPrintable(refused.err));
        QCOMPARE(mc1Writes(m.plcA), 1);
        VERIFY_EXIT(m.plcA.cli({"mc", "restore", path, "--replacement"}), 0);
        QCOMPARE(mc1Writes(m.plcA), 2);
    }
};

QTEST_GUILESS_MAIN(TestE2eMachineIdentity)
#include "tst_e2e_machine_identity.moc"
