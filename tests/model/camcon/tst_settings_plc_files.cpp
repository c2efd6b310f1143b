// The one reader and writer of settings and PLC files (used by the project
// file and by cambench-cli settings/plc read/write).
#include "model/camcon/plc_file.h"
#include "model/camcon/settings_file.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QtTest>

using namespace cambench;

class TestSettingsPlcFiles : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void settingsRoundTrip() {
        const SystemSettings settings{
            {QStringLiteral("cableLength"), qint64(17)},
            {QStringLiteral("actualValueFormat"), QStringLiteral("##.#")}};
        const Result<SystemSettings> again = settingsFileFromJson(settingsFileToJson(settings));
        QVERIFY2(again.ok(), qPrintable(again.error().message));
        QCOMPARE(*again, settings);
    }

    void deviceValueOutsideTheRangeLoads() {
        // specialEncoder.incremental.divider 0 is what the demo device holds.
        const QByteArray bytes =
            R"({"format":"cambench-settings","version":1,"settings":{"specialEncoder.incremental.divider":0}})";
        const Result<SystemSettings> settings = settingsFileFromJson(bytes);
        QVERIFY2(settings.ok(), qPrintable(settings.error().message));
        QCOMPARE(settings->value(QStringLiteral("specialEncoder.incremental.divider")).toLongLong(),
                 0);
        QCOMPARE(validateSettings(*settings).size(), 1);
    }

    void unknownSettingAndWrongTypeAreRefusedWithTheirPath() {
        const Result<SystemSettings> unknown = settingsFileFromJson(
            R"({"format":"cambench-settings","version":1,"settings":{"warpDrive":1}})");
        QVERIFY(!unknown.ok());
        QCOMPARE(unknown.error().message,
                 QStringLiteral("settings.warpDrive: there is no such setting."));
        const Result<SystemSettings> text = settingsFileFromJson(
            R"({"format":"cambench-settings","version":1,"settings":{"cableLength":"long"}})");
        QVERIFY(!text.ok());
        QVERIFY2(text.error().message.startsWith(QStringLiteral("settings.cableLength: ")),
                 qPrintable(text.error().message));
    }

    void aPlcFileIsNoSettingsFile() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("plc.json"));
        QVERIFY(savePlcFile(path, {}).ok());
        const Result<SystemSettings> settings = loadSettingsFile(path);
        QVERIFY(!settings.ok());
        QVERIFY2(
            settings.error().message.startsWith(path + QStringLiteral(": This is not a "
                                                                      "CamBench settings file")),
            qPrintable(settings.error().message));
    }

    void plcRoundTripWritesLetters() {
        PlcNetwork network;
        network.area = PlcNetwork::X;
        network.number = 7;
        network.value = -3;
        network.reset = 0xBEEF;
        network.symbols[29] = 0xFFFF;
        const QByteArray bytes = plcFileToJson({network});
        QVERIFY(bytes.contains("\"area\": \"X\""));
        const Result<QList<PlcNetwork>> again = plcFileFromJson(bytes);
        QVERIFY2(again.ok(), qPrintable(again.error().message));
        QCOMPARE(again->size(), 1);
        QVERIFY(again->first() == network);
    }

    void plcFileRefusesBadEntriesWithTheirPath_data() {
        QTest::addColumn<QByteArray>("network");
        QTest::addColumn<QString>("expected");
        const QByteArray symbols = "[0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0]";
        QTest::newRow("area")
            << QByteArray(R"({"area":"Q","number":1,"value":0,"reset":0,"symbols":)" + symbols +
                          "}")
            << QStringLiteral("networks[0].area: the area \"Q\" is none of O, P, M, X.");
        QTest::newRow("symbols")
            << QByteArray(R"({"area":"M","number":1,"value":0,"reset":0,"symbols":[1,2]})")
            << QStringLiteral("networks[0].symbols: 2 symbols, expected 30 (5 paths of 6).");
        QTest::newRow("reset")
            << QByteArray(R"({"area":"M","number":1,"value":0,"reset":70000,"symbols":)" + symbols +
                          "}")
            << QStringLiteral("networks[0].reset: reset field 70000 is outside 0..65535.");
    }

    void plcFileRefusesBadEntriesWithTheirPath() {
        QFETCH(QByteArray, network);
        QFETCH(QString, expected);
        const Result<QList<PlcNetwork>> networks = plcFileFromJson(
            R"({"format":"cambench-plc","version":1,"networks":[)" + network + "]}");
        QVERIFY(!networks.ok());
        QCOMPARE(networks.error().message, expected);
    }

    void plcNetworkListedTwiceIsRefused() {
        PlcNetwork network;
        network.area = PlcNetwork::O;
        const Result<QList<PlcNetwork>> networks =
            plcFileFromJson(plcFileToJson({network, network}));
        QVERIFY(!networks.ok());
        QVERIFY2(networks.error().message.contains(QLatin1String("O0 appears twice")),
                 qPrintable(networks.error().message));
    }
};

QTEST_GUILESS_MAIN(TestSettingsPlcFiles)
#include "tst_settings_plc_files.moc"
