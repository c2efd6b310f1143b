// Issue 15, end to end: the real cambench-cli against the real cambench-sim
// on a pseudo-terminal (QSerialPort, RTS/CTS as the protocol's default):
// identity, objects in every written form, a refusal with the drive's
// number, RS485 addressing and scan, the motion sequence, watch, and the
// parameter set workflow (backup → change → verify differs → restore →
// verify equal; another drive type refused unless forced).
#include "../e2e_support.h"

#include <QTest>

using namespace cambench::e2e;

class TestE2eCompax3 : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void objectsOnRs232() {
        SimSession session(QStringLiteral("compax3"));
        START_SIM(session);
        const CliRun info = session.cli({"c3", "info"});
        VERIFY_EXIT(info, 0);
        QVERIFY2(info.out.contains(QLatin1String("serial: C3-4711-0815\ntype: S025V2\n")),
                 qPrintable(info.out));

        const CliRun read = session.cli({"c3", "read", "680.5", "o1901.1", "O 1902,1", "$76D.$1"});
        VERIFY_EXIT(read, 0);
        QCOMPARE(read.out, QStringLiteral("680.5 = 0\n1901.1 = 100\n1902.1 = 200\n1901.1 = 100\n"));
        const CliRun json = session.cli({"c3", "read", "1000.3", "--json"});
        VERIFY_EXIT(json, 0);
        QVERIFY2(json.out.contains(QLatin1String("\"1000.3\": \"1285\"")), qPrintable(json.out));

        const CliRun write = session.cli({"c3", "write", "1901.1=12.5", "1902.1=$20"});
        VERIFY_EXIT(write, 0);
        QCOMPARE(write.out, QStringLiteral("1901.1 = 12.5\n1902.1 = 32\n"));
        const CliRun comma = session.cli({"c3", "write", "1901.1=12,5"});
        VERIFY_EXIT(comma, 2);
        QVERIFY2(comma.err.contains(QLatin1String("decimal point")), qPrintable(comma.err));
        VERIFY_EXIT(session.cli({"c3", "write", "680.5=1"}), 2);
        VERIFY_EXIT(session.cli({"c3", "write", "1100.3=1"}), 2);

        // A dictionary that allows what the drive does not: the drive's
        // refusal, with its number.
        const QByteArray wide = R"({"format":"cambench-compax3-dictionary","version":1,
"objects":[{"object":"1905.1","name":"Set 1 mode","type":"integer","access":"rw","min":0,"max":9}]})";
        QVERIFY(writeBytes(session.path("wide.json"), wide));
        const CliRun refused =
            session.cli({"c3", "--dictionary", session.path("wide.json"), "write", "1905.1=7"});
        VERIFY_EXIT(refused, 1);
        QVERIFY2(refused.err.contains(QLatin1String("!0004")), qPrintable(refused.err));
        QVERIFY(writeBytes(session.path("broken.json"), wide.left(80)));
        const CliRun broken =
            session.cli({"c3", "--dictionary", session.path("broken.json"), "read", "680.5"});
        VERIFY_EXIT(broken, 4);
        QVERIFY2(broken.err.contains(QLatin1String("line 2")), qPrintable(broken.err));
    }

    void motionAndWatch() {
        SimSession session(QStringLiteral("compax3"));
        START_SIM(session);
        const CliRun powerless = session.cli({"c3", "move", "1", "--target", "10"});
        VERIFY_EXIT(powerless, 1);
        QVERIFY2(powerless.err.contains(QLatin1String("enable it first")),
                 qPrintable(powerless.err));
        VERIFY_EXIT(session.cli({"c3", "enable"}), 0);
        const CliRun move =
            session.cli({"c3", "move", "2", "--target", "25.5", "--velocity", "5000"});
        VERIFY_EXIT(move, 0);
        QTest::qWait(200);
        const CliRun watch =
            session.cli({"c3", "watch", "680.5", "1000.4", "--count", "2", "--interval", "50"});
        VERIFY_EXIT(watch, 0);
        QCOMPARE(watch.out.count(QLatin1String("680.5 = 25.5  1000.4 = 2")), 2);
        const CliRun status = session.cli({"c3", "status"});
        VERIFY_EXIT(status, 0);
        QVERIFY2(status.out.contains(QLatin1String("b9 position reached: 1")),
                 qPrintable(status.out));
        QVERIFY(status.out.contains(QLatin1String("last error: no error")));
        VERIFY_EXIT(session.cli({"c3", "jog", "+"}), 0);
        const CliRun stop = session.cli({"c3", "stop"});
        VERIFY_EXIT(stop, 0);
        QVERIFY2(stop.out.contains(QLatin1String("\naxis: powered, standing at")),
                 qPrintable(stop.out));
        // Enable on a powered drive: nothing sent (it never drops power).
        const CliRun again = session.cli({"c3", "enable"});
        VERIFY_EXIT(again, 0);
        QVERIFY2(again.out.startsWith(QLatin1String("note: the drive is powered already: nothing "
                                                    "was sent")),
                 qPrintable(again.out));
    }

    void aStopNeverPowersTheDrive() {
        // Issue 35 item 2: `c3 disable`, then `c3 stop`: the STOP finds the
        // drive powerless and sends nothing; it stays powerless.
        SimSession session(QStringLiteral("compax3"));
        START_SIM(session);
        VERIFY_EXIT(session.cli({"c3", "enable"}), 0);
        VERIFY_EXIT(session.cli({"c3", "disable"}), 0);
        const CliRun stop = session.cli({"c3", "stop"});
        VERIFY_EXIT(stop, 0);
        QVERIFY2(stop.out.startsWith(QLatin1String("note: not powered: nothing to stop (nothing "
                                                   "was sent)\naxis: powerless at")),
                 qPrintable(stop.out));
        const CliRun status = session.cli({"c3", "status"});
        VERIFY_EXIT(status, 0);
        QVERIFY2(status.out.contains(QLatin1String("b10 powerless: 1")), qPrintable(status.out));
    }

    // Issue 35 item 9: a drive whose answers come 150 ms, 400 ms or 1 s
    // late (the first-byte time is about 0.1 s): every value is its own
    // request's, never the one before's.
    void lateAnswersAreNeverAnotherRequests_data() {
        QTest::addColumn<QString>("delay");
        QTest::newRow("150 ms") << QStringLiteral("150");
        QTest::newRow("400 ms") << QStringLiteral("400");
        QTest::newRow("1 s") << QStringLiteral("1000");
    }

    void lateAnswersAreNeverAnotherRequests() {
        QFETCH(QString, delay);
        SimSession session(QStringLiteral("compax3"));
        START_SIM(session, {"--delay", delay});
        const CliRun read = session.cli({"c3", "read", "1.4", "680.5", "1901.3"});
        VERIFY_EXIT(read, 0);
        QCOMPARE(read.out, QStringLiteral("1.4 = C3-4711-0815\n680.5 = 0\n1901.3 = 300\n"));
        const CliRun info = session.cli({"c3", "info"});
        VERIFY_EXIT(info, 0);
        QVERIFY2(info.out.contains(QLatin1String("serial: C3-4711-0815\ntype: S025V2\naxis: "
                                                 "powerless at 0\nlast error: no error\n")),
                 qPrintable(info.out));
        // The STOP's status read is late too: still read as powerless.
        const CliRun stop = session.cli({"c3", "stop"});
        VERIFY_EXIT(stop, 0);
        QVERIFY2(stop.out.startsWith(QLatin1String("note: not powered: nothing to stop")),
                 qPrintable(stop.out));
    }

    void anAcknowledgedCommandWhoseReadBackIsRefusedIsDone() {
        // Issue 27 item 2: every read-back refused (!0005); the jog was
        // acknowledged, so it is done: exit 0 with the note.
        SimSession session(QStringLiteral("compax3"));
        START_SIM(session, {"--refuse", "1000.3,550.1,680.5,1000.4,1100.3"});
        const CliRun jog = session.cli({"c3", "jog", "+"});
        VERIFY_EXIT(jog, 0);
        QVERIFY2(jog.out.startsWith(QLatin1String("done: jog the axis in + direction "
                                                  "(acknowledged by the drive)")),
                 qPrintable(jog.out));
        QVERIFY2(jog.err.contains(QLatin1String("could not be read back")) &&
                     jog.err.contains(QLatin1String("!0005")),
                 qPrintable(jog.err));
        VERIFY_EXIT(session.cli({"c3", "stop"}), 0);
    }

    void aScanNeedsNeitherProtocolNorAddress() {
        SimSession session{QString()};
        START_SIM(session, {"--family", "compax3", "--rs485", "--address", "12"});
        const CliRun scan = session.cli({"--family", "compax3", "c3", "scan"});
        VERIFY_EXIT(scan, 0);
        QCOMPARE(scan.out, QStringLiteral("12\n"));
    }

    void aDriveLackingObjectsBacksUpVerifiesAndRestores() {
        // Issue 29 item 2: a firmware without set 0; the backup records
        // those objects as not on this drive and exits 0.
        SimSession session(QStringLiteral("compax3"));
        START_SIM(session, {"--lacks", "1901.0,1902.0,1905.0,1906.0,1907.0,1908.0"});
        const QString file = session.path("lacking.json");
        const CliRun backup = session.cli({"c3", "backup", "-o", file});
        VERIFY_EXIT(backup, 0);
        QVERIFY2(backup.out.contains(QLatin1String("1901.0: not on this drive")),
                 qPrintable(backup.out));
        QVERIFY2(backup.out.contains(QLatin1String("saved 186 objects")) &&
                     backup.out.contains(QLatin1String("6 objects are not on this drive")),
                 qPrintable(backup.out));
        QVERIFY(readBytes(file).contains("\"absent\""));
        const CliRun verify = session.cli({"c3", "verify", file});
        VERIFY_EXIT(verify, 0);
        QVERIFY2(verify.out.contains(QLatin1String("equal: 192 items compared")) &&
                     verify.out.contains(QLatin1String("6 objects are not on this drive")),
                 qPrintable(verify.out));
        VERIFY_EXIT(session.cli({"c3", "write", "1901.3=7"}), 0);
        const CliRun restore = session.cli({"c3", "restore", file});
        VERIFY_EXIT(restore, 0);
        QVERIFY2(restore.out.contains(QLatin1String("186 items: 1 written, 185 unchanged")),
                 qPrintable(restore.out));

        // A file of a drive with set 0 on a drive without it: said, not written.
        SimSession full(QStringLiteral("compax3"));
        START_SIM(full);
        const QString fullFile = full.path("full.json");
        VERIFY_EXIT(full.cli({"c3", "backup", "-o", fullFile}), 0);
        const CliRun differs = session.cli({"c3", "verify", fullFile});
        VERIFY_EXIT(differs, 1);
        QVERIFY2(differs.out.contains(QStringLiteral("1901.0 Set 0 target 0 → not on this drive")),
                 qPrintable(differs.out));
        const CliRun partial = session.cli({"c3", "restore", fullFile});
        QVERIFY2(partial.exitCode != 0, describe(partial).constData());
        QVERIFY2(partial.out.contains(QLatin1String("not on this drive")) &&
                     partial.out.contains(QLatin1String("not written")),
                 qPrintable(partial.out));
    }

    void rs485AddressAndScan() {
        SimSession session(QStringLiteral("compax3-rs485"));
        START_SIM(session, {"--address", "12"});
        const CliRun scan = session.cli({"c3", "scan"});
        VERIFY_EXIT(scan, 0);
        QCOMPARE(scan.out, QStringLiteral("12\n"));
        const CliRun read = session.cli({"--address", "12", "c3", "read", "1901.3"});
        VERIFY_EXIT(read, 0);
        QCOMPARE(read.out, QStringLiteral("1901.3 = 300\n"));
        const CliRun other = session.cli({"--address", "13", "c3", "read", "1901.3"});
        VERIFY_EXIT(other, 3);
        QVERIFY2(other.err.contains(QLatin1String("address 13")), qPrintable(other.err));
    }

    void parameterSetWorkflow() {
        SimSession session(QStringLiteral("compax3"));
        START_SIM(session);
        const QString file = session.path("drive.json");
        const CliRun backup = session.cli({"c3", "backup", "-o", file});
        VERIFY_EXIT(backup, 0);
        QVERIFY2(backup.out.startsWith(QLatin1String("saved 192 objects of Compax3 S025V2")),
                 qPrintable(backup.out));
        VERIFY_EXIT(session.cli({"c3", "verify", file}), 0);
        VERIFY_EXIT(session.cli({"c3", "write", "1901.4=-7.5", "1906.9=50"}), 0);
        const CliRun differs = session.cli({"c3", "verify", file});
        VERIFY_EXIT(differs, 1);
        QVERIFY2(differs.out.contains(QStringLiteral("1901.4 Set 4 target 400 → -7.5")),
                 qPrintable(differs.out));
        QVERIFY(differs.out.contains(QLatin1String("2 differences in 192 items compared")));
        const CliRun restore = session.cli({"c3", "restore", file, "--store"});
        VERIFY_EXIT(restore, 0);
        // The two objects, then the two sets they are in stored (1904.n = $32).
        QVERIFY2(restore.out.contains(QLatin1String("194 items: 4 written, 190 unchanged")),
                 qPrintable(restore.out));
        QVERIFY(restore.out.contains(QLatin1String("(1904.4 = $32): written")));
        QVERIFY(restore.out.contains(QLatin1String("(1904.9 = $32): written")));
        VERIFY_EXIT(session.cli({"c3", "verify", file}), 0);

        // A replacement drive of another type.
        SimSession other(QStringLiteral("compax3"));
        START_SIM(other, {"--drive-type", "S150V4"});
        const CliRun refused = other.cli({"c3", "restore", file});
        VERIFY_EXIT(refused, 4);
        QVERIFY2(refused.err.contains(QLatin1String("another device answers: expected type "
                                                    "S025V2, found type S150V4")),
                 qPrintable(refused.err));
        // Accepted as the replacement, another type still needs --force.
        const CliRun otherType = other.cli({"c3", "restore", file, "--replacement"});
        VERIFY_EXIT(otherType, 4);
        QVERIFY2(otherType.err.contains(QLatin1String("nothing was written")),
                 qPrintable(otherType.err));
        VERIFY_EXIT(other.cli({"c3", "restore", file, "--replacement", "--force"}), 0);

        QByteArray tampered = readBytes(file);
        tampered.replace("\"400\"", "\"401\"");
        QVERIFY(writeBytes(session.path("tampered.json"), tampered));
        VERIFY_EXIT(session.cli({"c3", "restore", session.path("tampered.json")}), 4);
    }
};

QTEST_GUILESS_MAIN(TestE2eCompax3)
#include "tst_e2e_compax3.moc"
