#include "model/camcon/csv_io.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace cambench;

namespace {

Tracks sampleTracks() {
    Tracks tracks;
    tracks.insert(1, Track{1, {{10, 50}, {300, 20}}});
    tracks.insert(12, Track{12, {{0, 359}}});
    return tracks;
}

QString errorOf(const Error& error) {
    return error.message;
}

}  // namespace

class TestCsvIo : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void camsExportIsSortedWithHeader() {
        Tracks tracks = sampleTracks();
        tracks[1].cams = {{300, 20}, {10, 50}};
        QCOMPARE(camsToCsv(tracks), QByteArray("output,cam,on,off\n"
                                               "1,1,10,50\n"
                                               "1,2,300,20\n"
                                               "12,1,0,359\n"));
    }

    void camsRoundTrip() {
        const Result<Tracks> imported = camsFromCsv(camsToCsv(sampleTracks()));
        QVERIFY2(imported.ok(), qPrintable(imported.error().message));
        QCOMPARE(*imported, sampleTracks());
    }

    void camsImportAcceptsAnyRowOrderCrLfAndBlankLines() {
        const Result<Tracks> imported = camsFromCsv(
            "\xEF\xBB\xBFoutput,cam,on,off\r\n12,1,0,359\r\n\r\n1,2,300,20\r\n1,1,10,50\r\n");
        QVERIFY2(imported.ok(), qPrintable(imported.error().message));
        QCOMPARE(*imported, sampleTracks());
    }

    void camsImportReportsLineAndImportsNothing_data() {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("expected");
        QTest::newRow("header") << QByteArray("output;cam;on;off\n1;1;2;3\n")
                                << QStringLiteral("Line 1: the header must be");
        QTest::newRow("not a number")
            << QByteArray("output,cam,on,off\n1,1,10,50\n1,2,abc,60\n")
            << QStringLiteral("Line 3: switch-on point \"abc\" is not a whole number");
        QTest::newRow("fields") << QByteArray("output,cam,on,off\n1,1,10\n")
                                << QStringLiteral("Line 2: 3 fields, expected 4");
        QTest::newRow("output zero") << QByteArray("output,cam,on,off\n0,1,10,50\n")
                                     << QStringLiteral("Line 2: output 0 is outside");
        QTest::newRow("duplicate")
            << QByteArray("output,cam,on,off\n1,1,10,50\n\n1,1,60,70\n")
            << QStringLiteral("Line 4: output 1 has a cam 1 already (line 2)");
        QTest::newRow("gap") << QByteArray("output,cam,on,off\n1,1,10,50\n1,3,60,70\n")
                             << QStringLiteral("Line 3: cam 3 of output 1, but cam 2 is missing");
        QTest::newRow("too big") << QByteArray("output,cam,on,off\n1,1,10,99999999999\n")
                                 << QStringLiteral(
                                        "Line 2: switch-off point 99999999999 is outside");
        QTest::newRow("quote") << QByteArray("output,cam,on,off\n1,1,\"10,50\n")
                               << QStringLiteral("Line 2: a quoted field has no closing quote");
        QTest::newRow("not utf8") << QByteArray("output,cam,on,off\n1,1,\xff,2\n")
                                  << QStringLiteral("not UTF-8");
    }

    void camsImportReportsLineAndImportsNothing() {
        QFETCH(QByteArray, content);
        QFETCH(QString, expected);
        const Result<Tracks> imported = camsFromCsv(content);
        QVERIFY(!imported.ok());
        QCOMPARE(imported.error().kind, ErrorKind::InvalidData);
        QVERIFY2(imported.error().message.contains(expected), qPrintable(imported.error().message));
        QVERIFY(imported.error().message.endsWith(QStringLiteral("Nothing was imported.")));
    }

    void deadTimesRoundTripAndExport() {
        const DeadTimes deadTimes{{2, 15}, {1, 0}, {10, 9999}};
        QCOMPARE(deadTimesToCsv(deadTimes), QByteArray("output,deadtime\n1,0\n2,15\n10,9999\n"));
        const Result<DeadTimes> imported = deadTimesFromCsv(deadTimesToCsv(deadTimes));
        QVERIFY(imported.ok());
        QCOMPARE(*imported, deadTimes);
    }

    void deadTimesImportErrors() {
        Result<DeadTimes> imported = deadTimesFromCsv("output,deadtime\n1,5\n2,-1\n");
        QVERIFY(!imported.ok());
        QVERIFY(errorOf(imported.error()).startsWith(QStringLiteral("Line 3: dead time -1")));
        imported = deadTimesFromCsv("output,deadtime\n1,5\n1,6\n");
        QVERIFY(!imported.ok());
        QVERIFY(errorOf(imported.error())
                    .startsWith(QStringLiteral("Line 3: output 1 has a dead time already")));
        imported = deadTimesFromCsv("output,deadtime\n1,1.5\n");
        QVERIFY(!imported.ok());
    }

    void analogueCamsRoundTripAndErrors() {
        const QList<AnalogueCamTrack> tracks{AnalogueCamTrack{2, {{0, 100}, {90, -5}}},
                                             AnalogueCamTrack{3, {}}};
        const QByteArray csv = analogueCamsToCsv(tracks);
        QCOMPARE(csv, QByteArray("output,position,value\n2,0,100\n2,90,-5\n3,,\n"));
        const Result<QList<AnalogueCamTrack>> back = analogueCamsFromCsv(csv);
        QVERIFY2(back.ok(), qPrintable(back.error().message));
        QCOMPARE(*back, tracks);
        const Result<QList<AnalogueCamTrack>> mixed =
            analogueCamsFromCsv("output,position,value\n3,1,2\n3,,\n");
        QVERIFY(!mixed.ok());
        QVERIFY2(mixed.error().message.contains(QLatin1String("Line 3")),
                 qPrintable(mixed.error().message));
        const Result<QList<AnalogueCamTrack>> noOutput =
            analogueCamsFromCsv("output,position,value\n15,1,2\n");
        QVERIFY(!noOutput.ok());
        QVERIFY2(noOutput.error().message.contains(QLatin1String("Line 2")),
                 qPrintable(noOutput.error().message));
    }

    void namesRoundTripWithQuotes() {
        Names names;
        names.outputs = {{1, QStringLiteral("Glue, hot")},
                         {2, QStringLiteral("Say \"hi\"")},
                         {3, QStringLiteral(" padded ")},
                         {4, QString()}};
        names.programs = {{0, QStringLiteral("Über")}};
        const QByteArray csv = namesToCsv(names);
        QCOMPARE(csv, QByteArray("kind,number,name\n"
                                 "output,1,\"Glue, hot\"\n"
                                 "output,2,\"Say \"\"hi\"\"\"\n"
                                 "output,3,\" padded \"\n"
                                 "output,4,\n"
                                 "program,0,\xC3\x9C"
                                 "ber\n"));
        const Result<Names> imported = namesFromCsv(csv);
        QVERIFY2(imported.ok(), qPrintable(imported.error().message));
        QVERIFY(*imported == names);
    }

    void namesImportErrors() {
        Result<Names> imported = namesFromCsv("kind,number,name\noutput,1,a\nmotor,2,b\n");
        QVERIFY(!imported.ok());
        QVERIFY(errorOf(imported.error()).startsWith(QStringLiteral("Line 3: kind \"motor\"")));
        imported = namesFromCsv("kind,number,name\nprogram,0,\"x\"y\n");
        QVERIFY(!imported.ok());
        QVERIFY(errorOf(imported.error())
                    .startsWith(QStringLiteral("Line 2: there is text after a closing quote")));
        imported = namesFromCsv("kind,number,name\noutput,1,0123456789012345678901\n");
        QVERIFY(!imported.ok());
        QVERIFY(errorOf(imported.error()).contains(QStringLiteral("at most 21")));
        imported = namesFromCsv("kind,number,name\noutput,0,zero\n");
        QVERIFY(!imported.ok());
        imported = namesFromCsv("kind,number,name\nprogram,0,zero\nprogram,0,again\n");
        QVERIFY(!imported.ok());
        QVERIFY(errorOf(imported.error()).contains(QStringLiteral("line 2")));
    }

    void fileWrappersRoundTripAndNameTheFile() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("cams.csv"));
        QVERIFY(saveCamsCsv(path, sampleTracks()).ok());
        const Result<Tracks> loaded = loadCamsCsv(path);
        QVERIFY(loaded.ok());
        QCOMPARE(*loaded, sampleTracks());

        const QString deadPath = dir.filePath(QStringLiteral("dead.csv"));
        QVERIFY(saveDeadTimesCsv(deadPath, {{1, 3}}).ok());
        QCOMPARE(*loadDeadTimesCsv(deadPath), (DeadTimes{{1, 3}}));
        const Result<Names> wrong = loadNamesCsv(deadPath);
        QVERIFY(!wrong.ok());
        QVERIFY(wrong.error().message.startsWith(deadPath + QStringLiteral(": Line 1")));
        QVERIFY(!loadCamsCsv(dir.filePath(QStringLiteral("missing.csv"))).ok());
    }
};

QTEST_GUILESS_MAIN(TestCsvIo)
#include "tst_csv_io.moc"
