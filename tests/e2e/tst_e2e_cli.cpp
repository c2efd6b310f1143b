// The real cambench-cli against the real cambench-sim on a pseudo-terminal.
#include "e2e_support.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSet>
#include <QTest>

using namespace cambench::e2e;

namespace {

// The rows of a test that runs once per CamCon protocol: the simulator and
// the cli speak it (SimSession).
// Cam-BUS runs as a test of its own (tst_e2e_cli_cambus in tests.cmake:
// this executable with CAMBENCH_E2E_CAMBUS set): its rows and cases there,
// the point-to-point rows here.
bool camBusRun() {
    return qEnvironmentVariableIsSet("CAMBENCH_E2E_CAMBUS");
}

void protocolRows() {
    QTest::addColumn<QString>("protocol");
    if (camBusRun()) {
        QTest::newRow("cambus") << QStringLiteral("cambus");
        return;
    }
    for (const char* protocol : {"standard", "3964r-n96", "3964r-e38"})
        QTest::newRow(protocol) << QString::fromLatin1(protocol);
}

// The point-to-point ones only.
void pointToPointRows() {
    QTest::addColumn<QString>("protocol");
    for (const char* protocol : {"standard", "3964r-n96", "3964r-e38"})
        QTest::newRow(protocol) << QString::fromLatin1(protocol);
}

}  // namespace

class TestE2eCli : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void infoPrintsIdentityAndCapacities_data() { protocolRows(); }
    void infoPrintsIdentityAndCapacities();
    void infoJsonIsAnObject_data() { protocolRows(); }
    void infoJsonIsAnObject();
    void camsEditRoundTrip_data() { protocolRows(); }
    void camsEditRoundTrip();
    void camsWriteRejectsOverlapAndLeavesDeviceUntouched_data() { protocolRows(); }
    void camsWriteRejectsOverlapAndLeavesDeviceUntouched();
    void camsWriteForBiggerDeviceSendsNoWriteCommand();
    void programOutsideTheDeviceReadsNoCams();
    void writeReportsEveryItem();
    void projectReadThenWriteChangesNothing();
    void projectOfAnotherProtocolKeepsTheLink();
    void deadTimesRoundTrip_data() { protocolRows(); }
    void deadTimesRoundTrip();
    void namesRoundTrip();
    void settingsChangeOneValue_data() { protocolRows(); }
    void settingsChangeOneValue();
    void usersListNeverShowsNumbers();
    void plcRoundTrip_data() { protocolRows(); }
    void plcRoundTrip();
    void multiuserScanListsExactlyTheDevices();
    void multiuserDeviceOptionReachesThatDevice();
    void scanNeedsMultiuser_data() { pointToPointRows(); }
    void scanNeedsMultiuser();
    void camBusScanListsEveryUser();
    void camBusDeviceOptionReachesThatDevice();
    void camBusBackupRestoreVerify();
    void usageErrorsExitTwoWithUsage();
    void familyOptionNamesTheFamilies();
    void rawPrintsReplyBody();
    void portsListsSerialPortsWithoutADevice();
    void guiHelpNeedsNoDisplay();
    void asciiOnlyCommandsExitOneNamingTheProtocol_data();
    void asciiOnlyCommandsExitOneNamingTheProtocol();
};

void TestE2eCli::infoPrintsIdentityAndCapacities() {
    QFETCH(QString, protocol);
    SimSession session(protocol);
    START_SIM(session);
    const CliRun run = session.cli({QStringLiteral("info")});
    VERIFY_EXIT(run, 0);
    QVERIFY(run.out.contains(QLatin1String("eprom: 11.10.1994\n")));
    QVERIFY(run.out.contains(QLatin1String("outputs: 32\n")));
    QVERIFY(run.out.contains(QLatin1String("maxPosition: 359\n")));
    QVERIFY(run.err.isEmpty());
}

void TestE2eCli::infoJsonIsAnObject() {
    QFETCH(QString, protocol);
    SimSession session(protocol);
    START_SIM(session);
    const CliRun run = session.cli({QStringLiteral("info"), QStringLiteral("--json")});
    VERIFY_EXIT(run, 0);
    const QJsonObject object = QJsonDocument::fromJson(run.out.toUtf8()).object();
    QCOMPARE(object.value(QStringLiteral("programs")).toInt(), 16);
    QCOMPARE(object.value(QStringLiteral("eprom")).toString(), QStringLiteral("11.10.1994"));
}

void TestE2eCli::camsEditRoundTrip() {
    QFETCH(QString, protocol);
    SimSession session(protocol);
    START_SIM(session);
    const QString before = session.path(QStringLiteral("before.csv"));
    VERIFY_EXIT(session.cli({"cams", "read", "--program", "0", "-o", before}), 0);
    QByteArray csv = readBytes(before);
    QVERIFY(csv.startsWith("output,cam,on,off\n"));
    // The edit: a new track on output 20 and output 1 replaced by one cam.
    QByteArray edited = "output,cam,on,off\n1,1,100,200\n20,1,5,50\n20,2,300,2\n";
    const QString editedPath = session.path(QStringLiteral("edited.csv"));
    QVERIFY(writeBytes(editedPath, edited));
    VERIFY_EXIT(session.cli({"cams", "write", "--program", "0", editedPath}), 0);

    const CliRun after = session.cli({"cams", "read", "--program", "0"});
    VERIFY_EXIT(after, 0);
    // Tracks the file lists equal it; the others are as before.
    QByteArray expected = "output,cam,on,off\n1,1,100,200\n";
    for (const QByteArray& line : csv.split('\n')) {
        if (line.isEmpty() || line.startsWith("output") || line.startsWith("1,") ||
            line.startsWith("20,"))
            continue;
        expected += line + '\n';
    }
    QList<QByteArray> expectedLines = expected.split('\n');
    expectedLines.append("20,1,5,50");
    expectedLines.append("20,2,300,2");
    QList<QByteArray> actualLines = after.out.toUtf8().split('\n');
    std::sort(expectedLines.begin(), expectedLines.end());
    std::sort(actualLines.begin(), actualLines.end());
    expectedLines.removeAll(QByteArray());
    actualLines.removeAll(QByteArray());
    QCOMPARE(actualLines, expectedLines);

    const CliRun one = session.cli({"cams", "read", "--program", "0", "--output", "20"});
    VERIFY_EXIT(one, 0);
    QCOMPARE(one.out, QStringLiteral("output,cam,on,off\n20,1,5,50\n20,2,300,2\n"));
}

void TestE2eCli::camsWriteRejectsOverlapAndLeavesDeviceUntouched() {
    QFETCH(QString, protocol);
    SimSession session(protocol);
    START_SIM(session);
    const CliRun before = session.cli({"cams", "read", "--program", "0"});
    VERIFY_EXIT(before, 0);
    const QString bad = session.path(QStringLiteral("bad.csv"));
    // Cam 2 overlaps cam 1, and 400 lies beyond ?IMAX (359).
    QVERIFY(writeBytes(bad, "output,cam,on,off\n1,1,10,100\n1,2,50,150\n2,1,0,400\n"));
    const CliRun run = session.cli({"cams", "write", "--program", "0", bad});
    VERIFY_EXIT(run, 4);
    QVERIFY(run.err.startsWith(QLatin1String("cambench-cli: ")));
    QVERIFY2(run.err.contains(QLatin1String("refused before anything was sent")),
             qPrintable(run.err));
    QVERIFY(run.err.contains(QLatin1String("overlaps cam 1 (10..100)")));
    const CliRun after = session.cli({"cams", "read", "--program", "0"});
    QCOMPARE(after.out, before.out);
}

void TestE2eCli::camsWriteForBiggerDeviceSendsNoWriteCommand() {
    // Issue 6, point 3: a file for a 96-output device to the simulator's
    // 32-output device is refused before any write command.
    SimSession session;
    START_SIM(session, {"--verbose"});
    QByteArray csv = "output,cam,on,off\n";
    for (int output = 1; output <= 96; ++output)
        csv += QByteArray::number(output) + ",1," + QByteArray::number(output * 100) + "," +
               QByteArray::number(output * 100 + 90) + "\n";
    const QString file = session.path(QStringLiteral("big.csv"));
    QVERIFY(writeBytes(file, csv));
    // A generous reply timeout: the logging simulator may be slow to start
    // under a sanitizer (a bound, not a speed check).
    const CliRun run = session.cli({"--timeout", "2000", "cams", "write", "--program", "0", file});
    VERIFY_EXIT(run, 4);
    QVERIFY2(run.err.contains(QLatin1String("outputs 33..96 do not exist on the device (it has "
                                            "1..32)")),
             qPrintable(run.err));
    QVERIFY(run.err.contains(QLatin1String("and ")));  // the list is bounded
    QVERIFY(run.err.count(u'\n') <= 12);
    // The simulator's log of received frames: reads only.
    const QList<QByteArray> log =
        readBytes(session.path(QStringLiteral("sim-stderr.log"))).split('\n');
    QVERIFY(log.size() > 5);
    for (const QByteArray& line : log) QVERIFY2(!line.contains("<- !"), line.constData());
}

// Issue 31, item 6: every command that reads program N checks it against
// the device with the same words (usecases::checkProgramNumber), before
// any cam is asked for.
void TestE2eCli::programOutsideTheDeviceReadsNoCams() {
    SimSession session;
    START_SIM(session, {"--verbose"});
    const QString refusal = QStringLiteral(
        "program 16 does not exist on the device (it has programs 0 to 15): choose one of those");
    for (const QStringList& args : {QStringList{"cams", "read", "--program", "16"},
                                    QStringList{"diff", "device", "/dev/null", "--program", "16"},
                                    QStringList{"timing", "--program", "16", "--speed", "100"}}) {
        // A program the device does not have: data that does not fit it (4).
        const CliRun run = session.cli(args);
        VERIFY_EXIT(run, 4);
        QVERIFY2(run.err.contains(refusal),
                 qPrintable(args.join(u' ') + QLatin1String(": ") + run.err));
    }
    // The identity was read each time (?EPROM), no cam and no program name.
    const QByteArray log = readBytes(session.path(QStringLiteral("sim-stderr.log")));
    QCOMPARE(log.count("<- ? EPROM"), 3);
    QVERIFY2(!log.contains("<- ? NF"), log.constData());
    QVERIFY2(!log.contains("<- ? PNAME"), log.constData());
    QVERIFY2(!log.contains("<- !"), log.constData());
}

void TestE2eCli::writeReportsEveryItem() {
    SimSession session;
    START_SIM(session);
    const QString file = session.path(QStringLiteral("cams.csv"));
    QVERIFY(writeBytes(file, "output,cam,on,off\n1,1,10,90\n1,2,180,270\n2,1,5,6\n"));
    const CliRun run = session.cli({"cams", "write", "--program", "0", file});
    VERIFY_EXIT(run, 0);
    QCOMPARE(run.out, QStringLiteral("program 0, output 1: unchanged\n"
                                     "program 0, output 2: written\n"
                                     "2 items: 1 written, 1 unchanged\n"));
}

void TestE2eCli::projectReadThenWriteChangesNothing() {
    SimSession session;
    START_SIM(session, {"--verbose"});
    const QString file = session.path(QStringLiteral("device.cambench"));
    const CliRun read = session.cli({"--timeout", "2000", "project", "read", "-o", file});
    VERIFY_EXIT(read, 0);
    // The demo device's own odd value is noted, and saved all the same.
    QVERIFY2(read.err.contains(QLatin1String("specialEncoder.incremental.divider")),
             qPrintable(read.err));
    const QJsonObject project = QJsonDocument::fromJson(readBytes(file)).object();
    QCOMPARE(project.value(QStringLiteral("programs")).toArray().size(), 16);
    QCOMPARE(project.value(QStringLiteral("readAt"))
                 .toObject()
                 .value(QStringLiteral("programs"))
                 .toArray()
                 .size(),
             16);
    QVERIFY(!readBytes(file).contains("4711"));  // user numbers only when asked for
    const qsizetype logBefore = readBytes(session.path(QStringLiteral("sim-stderr.log"))).size();
    const CliRun write = session.cli({"--timeout", "2000", "project", "write", file});
    VERIFY_EXIT(write, 0);
    QVERIFY2(write.out.contains(QLatin1String(" 0 written, ")), qPrintable(write.out));
    const QByteArray log = readBytes(session.path(QStringLiteral("sim-stderr.log"))).mid(logBefore);
    QVERIFY2(!log.contains("<- !"), log.constData());
}

// Issue 39: a table-interface device's project written to a CamCon on
// Standard switched it to 3964R ("settings configuration (..., protocol):
// written"); the next connection failed. Its communication settings are
// left out and named; asked for by name, they are written last and the
// report says what the next connection needs.
void TestE2eCli::projectOfAnotherProtocolKeepsTheLink() {
    SimSession table(QStringLiteral("3964r-n96"));
    START_SIM(table);
    const QString file = table.path(QStringLiteral("table.cambench"));
    VERIFY_EXIT(table.cli({"project", "read", "-o", file}), 0);
    QCOMPARE(QJsonDocument::fromJson(readBytes(file))
                 .object()
                 .value(QStringLiteral("settings"))
                 .toObject()
                 .value(QStringLiteral("protocol"))
                 .toInt(),
             4);
    SimSession standard;
    START_SIM(standard, {"--verbose"});
    const CliRun write = standard.cli({"project", "write", file});
    QVERIFY2(!write.out.contains(QLatin1String("protocol)")), qPrintable(write.out));
    QVERIFY2(write.out.contains(QLatin1String("Communication settings left out: Communication "
                                              "protocol 3964R (the device keeps Communication "
                                              "protocol Standard)")),
             qPrintable(write.out));
    const QByteArray log = readBytes(standard.path(QStringLiteral("sim-stderr.log")));
    QVERIFY2(!log.contains("<- !GSIO"), log.constData());
    const CliRun info = standard.cli({"info"});
    VERIFY_EXIT(info, 0);
    QVERIFY2(info.out.contains(QLatin1String("protocol: 1\n")), qPrintable(info.out));

    const CliRun asked =
        standard.cli({"project", "write", file, "--communication-settings", "protocol"});
    QVERIFY2(asked.err.contains(QLatin1String("note: protocol will be written last")),
             qPrintable(asked.err));
    QVERIFY2(asked.out.contains(QLatin1String("settings configuration (protocol): written")),
             qPrintable(asked.out));
    QVERIFY2(asked.out.contains(QLatin1String("Communication settings written: the next "
                                              "connection to this device needs Communication "
                                              "protocol 3964R.")),
             qPrintable(asked.out));
    // (The simulator goes on speaking Standard; a real device would not.)
    QVERIFY2(standard.cli({"info"}).out.contains(QLatin1String("protocol: 4\n")),
             "protocol 4 after it was asked for");
    const CliRun wrong =
        standard.cli({"project", "write", file, "--communication-settings", "baud"});
    VERIFY_EXIT(wrong, 2);
    QVERIFY2(wrong.err.contains(QLatin1String("takes deviceNumber,protocol")),
             qPrintable(wrong.err));
}

void TestE2eCli::deadTimesRoundTrip() {
    QFETCH(QString, protocol);
    SimSession session(protocol);
    START_SIM(session);
    const QString file = session.path(QStringLiteral("dt.csv"));
    QVERIFY(writeBytes(file, "output,deadtime\n5,321\n6,0\n"));
    VERIFY_EXIT(session.cli({"deadtimes", "write", file}), 0);
    const CliRun read = session.cli({"deadtimes", "read"});
    VERIFY_EXIT(read, 0);
    // Plain, or with the mode columns where the protocol reaches the modes.
    const auto hasRow = [&read](const char* row) {
        return read.out.contains(QLatin1String("\n%1\n").arg(QLatin1String(row))) ||
               read.out.contains(QLatin1String("\n%1,normal,").arg(QLatin1String(row)));
    };
    QVERIFY2(hasRow("5,321"), qPrintable(read.out));
    QVERIFY(hasRow("6,0"));
    QVERIFY(writeBytes(file, "output,deadtime\n5,100000\n"));  // beyond ?GTZKMAX
    VERIFY_EXIT(session.cli({"deadtimes", "write", file}), 4);
}

void TestE2eCli::namesRoundTrip() {
    SimSession session;
    START_SIM(session);
    const QString file = session.path(QStringLiteral("names.csv"));
    QVERIFY(
        writeBytes(file, "kind,number,name\noutput,4,Pusher\nprogram,3,\"Format \"\"C\"\"\"\n"));
    VERIFY_EXIT(session.cli({"names", "write", file}), 0);
    const QString out = session.path(QStringLiteral("out.csv"));
    VERIFY_EXIT(session.cli({"names", "read", "-o", out}), 0);
    const QByteArray names = readBytes(out);
    QVERIFY2(names.contains("output,4,Pusher\n"), names.constData());
    QVERIFY(names.contains("program,3,\"Format \"\"C\"\"\"\n"));
}

void TestE2eCli::settingsChangeOneValue() {
    QFETCH(QString, protocol);
    SimSession session(protocol);
    START_SIM(session);
    const QString file = session.path(QStringLiteral("settings.json"));
    VERIFY_EXIT(session.cli({"settings", "read", "-o", file}), 0);
    QJsonObject root = QJsonDocument::fromJson(readBytes(file)).object();
    QJsonObject settings = root.value(QStringLiteral("settings")).toObject();
    QVERIFY(settings.contains(QStringLiteral("cableLength")));
    const int changed = settings.value(QStringLiteral("cableLength")).toInt() + 17;
    settings.insert(QStringLiteral("cableLength"), changed);
    root.insert(QStringLiteral("settings"), settings);
    QVERIFY(writeBytes(file, QJsonDocument(root).toJson()));
    VERIFY_EXIT(session.cli({"settings", "write", file}), 0);

    const CliRun read = session.cli({"settings", "read"});
    VERIFY_EXIT(read, 0);
    const QJsonObject again = QJsonDocument::fromJson(read.out.toUtf8()).object();
    QCOMPARE(again.value(QStringLiteral("settings"))
                 .toObject()
                 .value(QStringLiteral("cableLength"))
                 .toInt(),
             changed);
}

void TestE2eCli::usersListNeverShowsNumbers() {
    SimSession session;
    START_SIM(session);
    const QString log = session.path(QStringLiteral("traffic.log"));
    const CliRun run = session.cli({"--log", log, "users", "list"});
    VERIFY_EXIT(run, 0);
    QVERIFY(run.out.contains(QLatin1String("Supervisor")));
    QVERIFY(run.out.contains(QLatin1String("*****")));
    // The demo device's access codes.
    for (const char* secret : {"4711", "1234"}) {
        QVERIFY2(!run.out.contains(QLatin1String(secret)), secret);
    }
    const QList<QByteArray> lines = readBytes(log).split('\n');
    int userLines = 0;
    for (const QByteArray& line : lines) {
        if (!line.contains("USER")) continue;
        ++userLines;
        QVERIFY2(!line.contains("4711") && !line.contains("1234"), line.constData());
        // Nor as hex bytes: "34 37 31 31" / "31 32 33 34".
        QVERIFY2(!line.contains("34 37 31 31") && !line.contains("31 32 33 34"), line.constData());
    }
    QVERIFY(userLines >= 4);
}

void TestE2eCli::plcRoundTrip() {
    QFETCH(QString, protocol);
    SimSession session(protocol);
    START_SIM(session);
    const QString file = session.path(QStringLiteral("plc.json"));
    VERIFY_EXIT(session.cli({"plc", "read", "-o", file}), 0);
    QJsonObject root = QJsonDocument::fromJson(readBytes(file)).object();
    QJsonArray networks = root.value(QStringLiteral("networks")).toArray();
    QJsonArray symbols;
    for (int i = 0; i < 30; ++i) symbols.append(i == 0 ? 0x0107 : 0);
    networks.append(QJsonObject{{QStringLiteral("area"), QStringLiteral("M")},
                                {QStringLiteral("number"), 3},
                                {QStringLiteral("value"), 2500},
                                {QStringLiteral("reset"), 0},
                                {QStringLiteral("symbols"), symbols}});
    root.insert(QStringLiteral("networks"), networks);
    QVERIFY(writeBytes(file, QJsonDocument(root).toJson()));
    VERIFY_EXIT(session.cli({"plc", "write", file}), 0);
    const CliRun read = session.cli({"plc", "read"});
    VERIFY_EXIT(read, 0);
    const QJsonArray again = QJsonDocument::fromJson(read.out.toUtf8())
                                 .object()
                                 .value(QStringLiteral("networks"))
                                 .toArray();
    // The file lists networks in device order; compare regardless of order.
    const auto asSet = [](const QJsonArray& array) {
        QSet<QByteArray> set;
        for (const QJsonValue& value : array) set.insert(QJsonDocument(value.toObject()).toJson());
        return set;
    };
    QCOMPARE(again.size(), networks.size());
    QCOMPARE(asSet(again), asSet(networks));
}

void TestE2eCli::multiuserScanListsExactlyTheDevices() {
    SimSession session;
    START_SIM(session, {"--protocol", "multiuser", "--devices", "0,5"});
    const CliRun run = session.cliMultiuser({"scan"});
    VERIFY_EXIT(run, 0);
    QCOMPARE(run.out, QStringLiteral("0\n5\n"));
}

void TestE2eCli::multiuserDeviceOptionReachesThatDevice() {
    SimSession session;
    START_SIM(session, {"--protocol", "multiuser", "--devices", "0,5"});
    const CliRun run = session.cliMultiuser({"--device", "5", "info"});
    VERIFY_EXIT(run, 0);
    QVERIFY(run.out.contains(QLatin1String("deviceNumber: 5\n")));
    const CliRun absent = session.cliMultiuser({"--device", "7", "--timeout", "100", "info"});
    VERIFY_EXIT(absent, 3);
}

void TestE2eCli::camBusScanListsEveryUser() {
    if (!camBusRun()) QSKIP("run by tst_e2e_cli_cambus");
    SimSession session(QStringLiteral("cambus"));
    START_SIM(session, {"--devices", "3,7", "--display", "12"});
    const CliRun run = session.cli({"scan"});
    VERIFY_EXIT(run, 0);
    QCOMPARE(run.out, QStringLiteral("3: CamCon\n7: CamCon\n12: other\n63: this PC\n"));
    const CliRun json = session.cli({"--pc-number", "40", "scan", "--json"});
    VERIFY_EXIT(json, 0);
    const QJsonArray users = QJsonDocument::fromJson(json.out.toUtf8()).array();
    QCOMPARE(users.size(), 4);
    QCOMPARE(users.at(2).toObject().value(QStringLiteral("number")).toInt(), 12);
    QCOMPARE(users.at(2).toObject().value(QStringLiteral("kind")).toString(),
             QStringLiteral("other"));
    QCOMPARE(users.at(3).toObject().value(QStringLiteral("number")).toInt(), 40);
    QCOMPARE(users.at(3).toObject().value(QStringLiteral("kind")).toString(),
             QStringLiteral("this PC"));
}

void TestE2eCli::camBusDeviceOptionReachesThatDevice() {
    if (!camBusRun()) QSKIP("run by tst_e2e_cli_cambus");
    SimSession session(QStringLiteral("cambus"));
    START_SIM(session, {"--devices", "3,7", "--display", "12"});
    const CliRun run = session.cli({"--device", "7", "info"});
    VERIFY_EXIT(run, 0);
    QVERIFY(run.out.contains(QLatin1String("deviceNumber: 7\n")));
    QVERIFY(run.out.contains(QLatin1String("protocol: 0\n")));  // Ser.mode Cam-BUS
    // Nobody has number 5: its TO stays unanswered, nothing was executed.
    const CliRun absent = session.cli({"--device", "5", "info"});
    VERIFY_EXIT(absent, 3);
    QVERIFY2(absent.err.contains(QLatin1String("device 5 did not take the request")),
             qPrintable(absent.err));
}

void TestE2eCli::camBusBackupRestoreVerify() {
    if (!camBusRun()) QSKIP("run by tst_e2e_cli_cambus");
    SimSession session(QStringLiteral("cambus"));
    START_SIM(session, {"--devices", "3,7", "--display", "12"});
    const QString image = session.path(QStringLiteral("seven.json"));
    VERIFY_EXIT(session.cli({"--device", "7", "backup", "-o", image}), 0);
    // Device 3 gets 7's EEPROM; then it equals the file.
    const CliRun differs = session.cli({"--device", "3", "verify", image});
    VERIFY_EXIT(differs, 1);
    const CliRun restored =
        session.cli({"--device", "3", "restore", image, "--force", "--no-safety-backup"});
    VERIFY_EXIT(restored, 0);
    VERIFY_EXIT(session.cli({"--device", "3", "verify", image}), 0);
}

void TestE2eCli::scanNeedsMultiuser() {
    QFETCH(QString, protocol);
    SimSession session(protocol);
    START_SIM(session);
    // The protocol has no bus: the device's side, not the command line's (1).
    const CliRun run = session.cli({"scan"});
    VERIFY_EXIT(run, 1);
    QVERIFY(run.err.contains(QLatin1String("--protocol multiuser")));
}

// Issue 39, item 4: a usage error is the error and one line saying where
// the help is, never the whole help; `help COMMAND` prints that command's lines.
void TestE2eCli::usageErrorsExitTwoWithUsage() {
    for (const QStringList& args :
         {QStringList{"frobnicate"}, QStringList{"cams", "read"},
          QStringList{"--baud", "fast", "info"}, QStringList{}, QStringList{"info", "--bogus"}}) {
        const CliRun run = runCli(args, 30000);
        VERIFY_EXIT(run, 2);
        QVERIFY2(run.err.startsWith(QLatin1String("cambench-cli: ")), qPrintable(run.err));
        QVERIFY2(!run.err.contains(QLatin1String("Usage: cambench-cli")), qPrintable(run.err));
        QCOMPARE(run.err.count(u'\n'), 2);
        QVERIFY2(run.err.contains(QLatin1String("Help: `cambench-cli ")), qPrintable(run.err));
    }
    const CliRun cams = runCli({"cams", "read"}, 30000);
    QVERIFY2(cams.err.endsWith(QLatin1String(
                 "Help: `cambench-cli help cams`, or `cambench-cli --help` for everything\n")),
             qPrintable(cams.err));
    const CliRun camsHelp = runCli({"help", "cams"}, 30000);
    VERIFY_EXIT(camsHelp, 0);
    QVERIFY2(camsHelp.out.contains(QLatin1String("  cams read --program P")) &&
                 camsHelp.out.contains(QLatin1String("  cams write --program P FILE")) &&
                 !camsHelp.out.contains(QLatin1String("deadtimes")),
             qPrintable(camsHelp.out));
    const CliRun mcHelp = runCli({"help", "mc"}, 30000);
    VERIFY_EXIT(mcHelp, 0);
    QVERIFY2(mcHelp.out.contains(QLatin1String("  mc axis N speed V")) &&
                 mcHelp.out.contains(QLatin1String("--parameters FILE")),
             qPrintable(mcHelp.out));
    VERIFY_EXIT(runCli({"help", "frobnicate"}, 30000), 2);
    const CliRun help = runCli({"--help"}, 30000);
    VERIFY_EXIT(help, 0);
    QVERIFY(help.out.contains(QLatin1String("exit 0 when equal")));
}

// Issue 13, point 4: --family picks the device family (camcon by default,
// so every existing command line works); an unknown one is named with the
// families there are; a command of another family says whose it is (an
// announced family: tst_fake_family).
void TestE2eCli::familyOptionNamesTheFamilies() {
    const CliRun camcon = runCli({"--family", "camcon", "info"}, 30000);
    VERIFY_EXIT(camcon, 0);
    QVERIFY2(camcon.out.contains(QLatin1String("eprom: ")), qPrintable(camcon.out));
    const CliRun unknown = runCli({"--family", "s7", "info"}, 30000);
    VERIFY_EXIT(unknown, 2);
    QVERIFY2(unknown.err.contains(QLatin1String("one of camcon, mc1, compax3, not \"s7\"")),
             qPrintable(unknown.err));
    const CliRun other = runCli({"--family", "compax3", "info"}, 30000);
    VERIFY_EXIT(other, 2);
    QVERIFY2(other.err.contains(QLatin1String("\"info\" is a command of the camcon family")) &&
                 other.err.contains(QLatin1String("--family compax3")),
             qPrintable(other.err));
    const CliRun help = runCli({"--help"}, 30000);
    QVERIFY2(help.out.contains(QLatin1String("--family")), qPrintable(help.out));
}

void TestE2eCli::rawPrintsReplyBody() {
    SimSession session;
    START_SIM(session);
    const CliRun run = session.cli({"raw", "?GPRGMAX"});
    VERIFY_EXIT(run, 0);
    QCOMPARE(run.out, QStringLiteral("GPRGMAX0010\n"));
}

void TestE2eCli::asciiOnlyCommandsExitOneNamingTheProtocol_data() {
    QTest::addColumn<QString>("protocol");
    QTest::addColumn<QStringList>("command");
    QTest::addColumn<QString>("capability");
    for (const char* protocol : {"3964r-n96", "3964r-e38"}) {
        const auto row = [protocol](const char* name, const QStringList& command,
                                    const char* capability) {
            QTest::newRow(qPrintable(
                QStringLiteral("%1 %2").arg(QLatin1String(protocol), QLatin1String(name))))
                << QString::fromLatin1(protocol) << command << QString::fromLatin1(capability);
        };
        row("backup", {"backup", "-o", "@image"}, "EEPROM backup");
        row("restore", {"restore", "--no-safety-backup", "@image"}, "EEPROM backup");
        row("verify", {"verify", "@image"}, "EEPROM backup");
        row("users", {"users", "list"}, "Users");
        row("names", {"names", "read"}, "names");
        row("raw", {"raw", "?GPRGMAX"}, "Typed requests");
    }
}

// What the protocol lacks is the device side's (exit 1), not a command line
// that cannot be understood (2); nothing is sent.
void TestE2eCli::asciiOnlyCommandsExitOneNamingTheProtocol() {
    QFETCH(QString, protocol);
    QFETCH(QStringList, command);
    QFETCH(QString, capability);
    // A real image, taken from a device that has EEPROM backup.
    SimSession ascii;
    START_SIM(ascii);
    const QString image = ascii.path(QStringLiteral("image.json"));
    VERIFY_EXIT(ascii.cli({"backup", "-o", image}), 0);
    command.replaceInStrings(QStringLiteral("@image"), image);

    SimSession session(protocol);
    START_SIM(session);
    const CliRun run = session.cli(command);
    VERIFY_EXIT(run, 1);
    QVERIFY2(run.err.contains(capability), qPrintable(run.err));
    QVERIFY2(run.err.contains(QLatin1String("ASCII protocol (Standard or Multiuser)")),
             qPrintable(run.err));
    QVERIFY(run.out.isEmpty());
}

void TestE2eCli::portsListsSerialPortsWithoutADevice() {
    // No port given and none opened: the list comes from the system alone.
    const CliRun json = runCli({QStringLiteral("ports"), QStringLiteral("--json")});
    QVERIFY(json.finished);
    QCOMPARE(json.exitCode, 0);
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(json.out.toUtf8(), &error);
    QVERIFY2(error.error == QJsonParseError::NoError && document.isArray(), qPrintable(json.out));
    for (const QJsonValue& port : document.array())
        QVERIFY(!port.toObject().value(QStringLiteral("port")).toString().isEmpty());
    const CliRun text = runCli({QStringLiteral("ports")});
    QCOMPARE(text.exitCode, 0);
    QVERIFY(!text.out.isEmpty());
}

void TestE2eCli::guiHelpNeedsNoDisplay() {
    // On ssh or a headless machine, `cambench --help` printed nothing and
    // aborted for want of a display (issue 12, point 8).
#ifndef CAMBENCH_GUI_EXE
    QSKIP("built without the desktop application (CAMBENCH_GUI=OFF)");
#else
    QProcess gui;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
        env.remove(QString::fromLatin1(name));
    gui.setProcessEnvironment(env);
    endWithThisTest(gui);
    for (const QString& option : {QStringLiteral("--help"), QStringLiteral("--version")}) {
        gui.start(QStringLiteral(CAMBENCH_GUI_EXE), {option});
        QVERIFY(gui.waitForFinished(hangBoundMs(30000)));
        QCOMPARE(gui.exitStatus(), QProcess::NormalExit);
        QCOMPARE(gui.exitCode(), 0);
        const QString out = QString::fromUtf8(gui.readAllStandardOutput());
        QVERIFY2(out.contains(option == QLatin1String("--help") ? QLatin1String("--port")
                                                                : QLatin1String("CamBench")),
                 qPrintable(out));
    }
#endif
}

QTEST_GUILESS_MAIN(TestE2eCli)
#include "tst_e2e_cli.moc"
