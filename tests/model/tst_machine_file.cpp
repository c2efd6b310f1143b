// Issue 30, item 1: the machine file. A device's keys are the command
// line's own option names; a wrong key, a duplicate or missing name, a
// value that is neither text nor a whole number is refused naming the
// device; the devices keep the file's order.
#include "model/machine/machine_file.h"

#include <QtTest>

using namespace cambench;

namespace {

// JSON written with ' for " (readable here; moc skips a file with raw strings).
QByteArray json(const char* text) {
    return QByteArray(text).replace('\'', '"');
}

}  // namespace

class TestMachineFile : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void thePressOfTheIssue() {
        const QByteArray text = json(
            "{'machine': 'Press 7', 'devices': ["
            "            {'name': 'cams', 'family': 'camcon', 'port': '/dev/ttyUSB0', 'protocol': "
            "'standard'},"
            "            {'name': 'press-plc', 'family': 'mc1', 'port': '/dev/ttyUSB1', 'variant': "
            "'mc200v2'},"
            "            {'name': 'feed', 'family': 'compax3', 'port': 'tcp://press7-ds:4001', "
            "'address': 3}],"
            "            'shaft': {'from': 'feed', 'to': 'cams'}}");
        const Result<MachineFile> machine = parseMachineFile(text, QStringLiteral("press7.json"));
        QVERIFY2(machine.ok(), qPrintable(machine.error().message));
        QCOMPARE(machine->machine, QStringLiteral("Press 7"));
        QCOMPARE(machine->devices.size(), 3);
        QCOMPARE(machine->devices.at(0).name, QStringLiteral("cams"));
        QCOMPARE(machine->devices.at(2).name, QStringLiteral("feed"));
        QCOMPARE(machine->devices.at(2).option(QStringLiteral("address")), QStringLiteral("3"));
        QCOMPARE(machine->devices.at(2).arguments(),
                 QStringList(
                     {"--family", "compax3", "--address", "3", "--port", "tcp://press7-ds:4001"}));
        QCOMPARE(machine->shaftFrom, QStringLiteral("feed"));
        QCOMPARE(machine->shaftTo, QStringLiteral("cams"));
        QVERIFY(!machine->shaftAxis && !machine->shaftPerTurn);  // the simulator's defaults
    }

    // The shaft's driving axis and its units per turn of the follower.
    void aShaftWithItsAxisAndUnitsPerTurn() {
        const QByteArray text = json(
            "{'machine': 'P', 'devices': ["
            "{'name': 'cams', 'family': 'camcon', 'port': 'sim'},"
            "{'name': 'plc', 'family': 'mc1', 'port': 'sim'}],"
            "'shaft': {'from': 'plc', 'to': 'cams', 'axis': 2, 'per-turn': 1000.5}}");
        const Result<MachineFile> machine = parseMachineFile(text, QStringLiteral("m.json"));
        QVERIFY2(machine.ok(), qPrintable(machine.error().message));
        QCOMPARE(machine->shaftAxis.value_or(0), 2);
        QCOMPARE(machine->shaftPerTurn.value_or(0), 1000.5);
    }

    void refusedNamingTheDevice_data() {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("says");
        const QByteArray ok = json("{'name': 'cams', 'family': 'camcon', 'port': 'sim'}");
        QTest::newRow("unknown key")
            << QByteArray(
                   json("{'machine': 'P', 'devices': [") + ok +
                   json(", {'name': 'feed', 'family': 'compax3', 'port': 'sim', 'adress': 3}]}"))
            << "device 2 (feed): unknown key \"adress\"";
        QTest::newRow("duplicate name")
            << QByteArray(json("{'machine': 'P', 'devices': [") + ok + "," + ok + "]}")
            << "device 2 (cams): the name is given twice";
        QTest::newRow("no name") << QByteArray(
                                        json("{'machine': 'P', 'devices': [{'family': 'mc1'}]}"))
                                 << "device 1 has no \"name\"";
        QTest::newRow("no port")
            << QByteArray(json("{'machine': 'P', 'devices': [{'name': 'a', 'family': 'mc1'}]}"))
            << "device 1 (a) has no \"port\"";
        QTest::newRow("fraction") << QByteArray(
                                         json("{'machine': 'P', 'devices': [{'name': 'a', "
                                              "'family': 'mc1', 'port': 'sim', 'baud': 9600.5}]}"))
                                  << "device 1 (a): \"baud\" must be text or a whole number";
        QTest::newRow("shaft to nobody")
            << QByteArray(json("{'machine': 'P', 'devices': [") + ok +
                          json("], 'shaft': {'from': 'feed', 'to': 'cams'}}"))
            << "(not \"feed\")";
        const QByteArray two = json("{'machine': 'P', 'devices': [") + ok +
                               json(", {'name': 'feed', 'family': 'compax3', 'port': 'sim'}], ");
        QTest::newRow("shaft to itself")
            << QByteArray(two + json("'shaft': {'from': 'feed', 'to': 'feed'}}"))
            << "runs from \"feed\" to itself";
        QTest::newRow("shaft not an object")
            << QByteArray(two + json("'shaft': 'feed'}")) << "the shaft is {\"from\": DEVICE";
        QTest::newRow("shaft key")
            << QByteArray(two + json("'shaft': {'from': 'feed', 'to': 'cams', 'ratio': 2}}"))
            << "the shaft has an unknown key \"ratio\"";
        QTest::newRow("shaft axis")
            << QByteArray(two + json("'shaft': {'from': 'feed', 'to': 'cams', 'axis': 0}}"))
            << "the driving axis of \"feed\"";
        QTest::newRow("shaft per turn")
            << QByteArray(two + json("'shaft': {'from': 'feed', 'to': 'cams', 'per-turn': -5}}"))
            << "how many units of \"feed\" turn \"cams\" once";
        QTest::newRow("no devices")
            << QByteArray(json("{'machine': 'P', 'devices': []}")) << "no \"devices\"";
        QTest::newRow("not json") << QByteArray("{\"machine\": ") << "not JSON at byte";
        QTest::newRow("unknown top key")
            << QByteArray(json("{'machine': 'P', 'device': []}")) << "unknown key \"device\"";
    }

    void refusedNamingTheDevice() {
        QFETCH(QByteArray, text);
        QFETCH(QString, says);
        const Result<MachineFile> machine = parseMachineFile(text, QStringLiteral("m.json"));
        QVERIFY(!machine.ok());
        QCOMPARE(machine.error().kind, ErrorKind::InvalidData);
        QVERIFY2(machine.error().message.startsWith(QLatin1String("Machine file m.json: ")),
                 qPrintable(machine.error().message));
        QVERIFY2(machine.error().message.contains(says), qPrintable(machine.error().message));
    }

    // Issue 36, item 6: a device's identity, once known, is recorded in the
    // file (after its options, on its line) and read back as it was.
    void identityRecordedAndReadBack() {
        const QByteArray text = json(
            "{'machine': 'P', 'devices': [{'name': 'feed', 'family': 'compax3', 'port': "
            "'sim', 'identity': {'type': 'S025V2', 'serial': 'C3-1001'}}]}");
        const Result<MachineFile> machine = parseMachineFile(text, QStringLiteral("m.json"));
        QVERIFY2(machine.ok(), qPrintable(machine.error().message));
        const DeviceIdentity& identity = machine->devices.at(0).identity;
        QCOMPARE(identity.value(QStringLiteral("serial")), QStringLiteral("C3-1001"));
        QCOMPARE(identity.text(), QStringLiteral("serial C3-1001, type S025V2"));
        QCOMPARE(machine->devices.at(0).arguments(),
                 QStringList({"--family", "compax3", "--port", "sim"}));  // no option
        const QByteArray written = machineFileJson(*machine);
        QVERIFY2(written.contains(json("'port': 'sim', 'identity': {'serial': 'C3-1001', "
                                       "'type': 'S025V2'}}")),
                 written.constData());
        QCOMPARE(parseMachineFile(written, QStringLiteral("m.json"))->devices.at(0).identity,
                 identity);
        // Not an object of texts: refused naming the device.
        const Result<MachineFile> wrong = parseMachineFile(
            json("{'machine': 'P', 'devices': [{'name': 'feed', 'family': 'compax3', 'port': "
                 "'sim', 'identity': {'serial': 1001}}]}"),
            QStringLiteral("m.json"));
        QVERIFY(!wrong.ok());
        QVERIFY2(wrong.error().message.contains(QLatin1String("device 1 (feed): identity: "
                                                              "\"serial\" must be a text")),
                 qPrintable(wrong.error().message));
    }

    // Issue 37: the items that change by themselves ("volatile"), read and
    // written back on the device's line; a range ending below its start or
    // a list of numbers is refused naming the device.
    void volatileItemsReadAndWrittenBack() {
        const QByteArray text = json(
            "{'machine': 'P', 'devices': [{'name': 'press-plc', 'family': 'mc1', 'port': "
            "'sim', 'volatile': ['V100-V199', 'V12']}]}");
        const Result<MachineFile> machine = parseMachineFile(text, QStringLiteral("m.json"));
        QVERIFY2(machine.ok(), qPrintable(machine.error().message));
        QCOMPARE(machine->devices.at(0).volatileItems, QStringList({"V100-V199", "V12"}));
        QCOMPARE(machine->devices.at(0).arguments(),
                 QStringList({"--family", "mc1", "--port", "sim"}));  // no option
        const QByteArray written = machineFileJson(*machine);
        QVERIFY2(written.contains(json("'port': 'sim', 'volatile': ['V100-V199', 'V12']}")),
                 written.constData());
        QCOMPARE(parseMachineFile(written, QStringLiteral("m.json"))->devices.at(0).volatileItems,
                 machine->devices.at(0).volatileItems);
        for (const char* wrong : {"'volatile': ['V199-V100']", "'volatile': [12]",
                                  "'volatile': 'V12'", "'volatile': ['']"}) {
            const Result<MachineFile> refused = parseMachineFile(
                json(QByteArray("{'machine': 'P', 'devices': [{'name': 'press-plc', 'family': "
                                "'mc1', 'port': 'sim', ") +
                     wrong + "}]}"),
                QStringLiteral("m.json"));
            QVERIFY2(!refused.ok(), wrong);
            QVERIFY2(refused.error().message.contains(QLatin1String("device 1 (press-plc)")),
                     qPrintable(refused.error().message));
        }
    }

    // The GUI's Save machine: name and family first, numbers as numbers, a
    // port that looks like a number stays text, one device a line; read
    // back it is the same machine, and written again the same bytes.
    void writtenAndReadBack() {
        MachineFile machine;
        machine.machine = QStringLiteral("Press \"7\"");
        machine.devices << MachineDevice{QStringLiteral("cams"),
                                         QStringLiteral("camcon"),
                                         {{QStringLiteral("port"), QStringLiteral("5")},
                                          {QStringLiteral("protocol"), QStringLiteral("standard")}},
                                         {},
                                         {}}
                        << MachineDevice{
                               QStringLiteral("feed"),
                               QStringLiteral("compax3"),
                               {{QStringLiteral("address"), QStringLiteral("3")},
                                {QStringLiteral("port"), QStringLiteral("tcp://ds:4001")}},
                               {},
                               {}};
        machine.shaftFrom = QStringLiteral("feed");
        machine.shaftTo = QStringLiteral("cams");
        const QByteArray text = machineFileJson(machine);
        QCOMPARE(text, json("{\n"
                            "  'machine': 'Press \\'7\\'',\n"
                            "  'devices': [\n"
                            "    {'name': 'cams', 'family': 'camcon', 'port': '5', 'protocol': "
                            "'standard'},\n"
                            "    {'name': 'feed', 'family': 'compax3', 'address': 3, 'port': "
                            "'tcp://ds:4001'}\n"
                            "  ],\n"
                            "  'shaft': {'from': 'feed', 'to': 'cams'}\n"
                            "}\n"));
        const Result<MachineFile> read = parseMachineFile(text, QStringLiteral("m.json"));
        QVERIFY2(read.ok(), qPrintable(read.error().message));
        QCOMPARE(read->machine, machine.machine);
        QCOMPARE(read->devices.size(), 2);
        QCOMPARE(read->devices.at(0).option(QStringLiteral("port")), QStringLiteral("5"));
        QCOMPARE(read->devices.at(1).option(QStringLiteral("address")), QStringLiteral("3"));
        QCOMPARE(machineFileJson(*read), text);

        // The shaft's axis and units a turn, when given, are saved too.
        machine.shaftAxis = 2;
        machine.shaftPerTurn = 1000.5;
        const QByteArray withShaft = machineFileJson(machine);
        QVERIFY2(
            withShaft.contains("\"shaft\": {\"from\": \"feed\", \"to\": \"cams\", \"axis\": 2, "
                               "\"per-turn\": 1000.5}"),
            withShaft.constData());
        const Result<MachineFile> again = parseMachineFile(withShaft, QStringLiteral("m.json"));
        QVERIFY2(again.ok(), qPrintable(again.error().message));
        QCOMPARE(again->shaftAxis, std::optional<int>(2));
        QCOMPARE(again->shaftPerTurn, std::optional<double>(1000.5));
        QCOMPARE(machineFileJson(*again), withShaft);
    }
};

QTEST_GUILESS_MAIN(TestMachineFile)
#include "tst_machine_file.moc"
