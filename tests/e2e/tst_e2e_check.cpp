// Issue 29: `cambench-cli check` end to end, the real cli against the real
// simulator on a pseudo-terminal, for every family and two CamCons that
// differ (with and without analogue outputs): every reading held, one
// verdict a line, --json and -o.
#include "e2e_support.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace cambench::e2e;

class TestE2eCheck : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void everyReadingHeld_data();
    void everyReadingHeld();
    void jsonReportToAFile();
    void mc1ParameterTableRefutedThenHeldWithTheControllersFile();
    void compax3DictionaryGivenWordsTheRefusals();
    void aTableOfAnotherFamilyIsRefusedBeforeTheCheck();
};

void TestE2eCheck::everyReadingHeld_data() {
    QTest::addColumn<QString>("protocol");
    QTest::addColumn<QStringList>("simArgs");
    QTest::addColumn<QString>("aHeldReading");
    QTest::newRow("camcon standard") << QString() << QStringList() << "held  ascii.?GTEMP";
    QTest::newRow("camcon multiuser")
        << "multiuser" << QStringList() << "held  multiuser.block_numbers";
    QTest::newRow("camcon cambus") << "cambus" << QStringList() << "held  cambus.token_round";
    QTest::newRow("camcon 3964r-n96")
        << "3964r-n96" << QStringList() << "held  table.analogue_outputs";
    QTest::newRow("camcon 3964r-n96 without analogue outputs")
        << "3964r-n96" << QStringList{"--analogue-outputs", "0"} << "it says 0";
    QTest::newRow("mc100v1") << "mc1" << QStringList{"--variant", "mc100v1"}
                             << "held  mc1.flag_addressing";
    QTest::newRow("mc200v2") << "mc1" << QStringList{"--variant", "mc200v2"} << "held  mc1.axes";
    QTest::newRow("mc100 ascii") << "mc1-ascii" << QStringList() << "held  mc1.variable_width";
    QTest::newRow("compax3") << "compax3" << QStringList() << "held  compax3.separators";
}

void TestE2eCheck::everyReadingHeld() {
    QFETCH(QString, protocol);
    QFETCH(QStringList, simArgs);
    QFETCH(QString, aHeldReading);
    SimSession session(protocol);
    START_SIM(session, simArgs);
    const CliRun check = session.cli({"check"});
    VERIFY_EXIT(check, 0);
    QVERIFY2(!check.out.contains(QLatin1String("refuted  ")), qPrintable(check.out));
    QVERIFY2(check.out.contains(aHeldReading), qPrintable(check.out));
    QVERIFY2(check.out.contains(QLatin1String(" 0 refuted")), qPrintable(check.out));
}

void TestE2eCheck::jsonReportToAFile() {
    SimSession session(QStringLiteral("3964r-n96"));
    START_SIM(session);
    const QString file = session.path(QStringLiteral("check.json"));
    const CliRun check = session.cli({"check", "--json", "-o", file});
    VERIFY_EXIT(check, 0);
    const QJsonObject report = QJsonDocument::fromJson(readBytes(file)).object();
    QCOMPARE(report.value(QStringLiteral("family")).toString(), QStringLiteral("camcon"));
    QCOMPARE(report.value(QStringLiteral("protocol")).toString(), QStringLiteral("3964r-n96"));
    QCOMPARE(report.value(QStringLiteral("refuted")).toInt(), 0);
    QCOMPARE(report.value(QStringLiteral("refusedRequests")).toInt(), 0);
    const QJsonArray results = report.value(QStringLiteral("results")).toArray();
    QVERIFY(results.size() > 50);
    for (const QJsonValue& result : results) {
        QVERIFY(!result.toObject().value(QStringLiteral("source")).toString().isEmpty());
    }
}

// A controller whose axis parameters start at 0x2000, not at the built-in
// guess's 0x1000: each parameter of the guess is refused and said with its
// number; with the controller's own table (a file) each one is held.
void TestE2eCheck::mc1ParameterTableRefutedThenHeldWithTheControllersFile() {
    SimSession session(QStringLiteral("mc1"));
    START_SIM(session, {"--variant", "mc200v2", "--parameter-base", "0x2000"});
    const CliRun guess = session.cli({"check"});
    VERIFY_EXIT(guess, 1);
    // Refused and said with its number and table; RDTABLE does not depend
    // on the table: the axes still hold.
    for (const char* said : {"refuted  mc1.axis_parameter.1.position", "parameter 4112 (0x1010)",
                             "[provisional: built-in guess", "held  mc1.axes"})
        QVERIFY2(guess.out.contains(QLatin1String(said)), qPrintable(guess.out));

    QByteArray csv = "name,axis,parameter\n";
    const char* names[] = {"position", "target", "status"};
    for (int axis = 1; axis <= 8; ++axis)
        for (int i = 0; i < 3; ++i)
            csv += QByteArray(names[i]) + ',' + QByteArray::number(axis) + ",0x" +
                   QByteArray::number(0x2000 + 0x10 * axis + i, 16) + '\n';
    const QString file = session.path(QStringLiteral("controller.csv"));
    QVERIFY(writeBytes(file, csv));
    const CliRun own = session.cli({"check", "--parameters", file});
    VERIFY_EXIT(own, 0);
    QVERIFY2(own.out.contains(QLatin1String("held  mc1.axis_parameter.8.status")),
             qPrintable(own.out));
    QVERIFY2(own.out.contains(QLatin1String("parameter 8322 (0x2082)")), qPrintable(own.out));
    QVERIFY2(own.out.contains(QStringLiteral("[%1]").arg(file)), qPrintable(own.out));
    QVERIFY2(!own.out.contains(QLatin1String("refuted  ")), qPrintable(own.out));
}

// A dictionary of the person's own, with its own words for the refusals:
// c3 read and check say them, and check tries its objects only.
void TestE2eCheck::compax3DictionaryGivenWordsTheRefusals() {
    SimSession session(QStringLiteral("compax3"));
    START_SIM(session);
    const QString file = session.path(QStringLiteral("own.json"));
    const QByteArray own =
        "{\"format\":\"cambench-compax3-dictionary\",\"version\":1,\"refusals\":["
        "{\"code\":\"0002\",\"meaning\":\"not in this firmware (own words)\",\"absent\":true},"
        "{\"code\":\"0006\",\"meaning\":\"asked in the wrong type (own words)\"}],"
        "\"objects\":[{\"object\":\"680.5\",\"name\":\"Actual position\",\"type\":\"real\","
        "\"access\":\"ro\",\"group\":\"Status\"}]}";
    QVERIFY(writeBytes(file, own));
    const CliRun read = session.cli({"c3", "--dictionary", file, "read", "9999.99"});
    QVERIFY2(read.err.contains(QLatin1String("not in this firmware (own words)")) ||
                 read.out.contains(QLatin1String("not in this firmware (own words)")),
             describe(read).constData());
    const CliRun check = session.cli({"check", "--dictionary", file});
    VERIFY_EXIT(check, 0);
    for (const QString& said :
         {QStringLiteral("held  compax3.refusal.0002"),
          QStringLiteral("not in this firmware (own words)"),
          QStringLiteral("held  compax3.object.680.5"), QStringLiteral("[%1]").arg(file)})
        QVERIFY2(check.out.contains(said), qPrintable(check.out));
    // Its objects only, not the shipped ones.
    QVERIFY2(!check.out.contains(QLatin1String("compax3.object.1.4")), qPrintable(check.out));
    // Without it: the shipped words, said as provisional.
    const CliRun shipped = session.cli({"check"});
    VERIFY_EXIT(shipped, 0);
    QVERIFY2(shipped.out.contains(QLatin1String("no such object")), qPrintable(shipped.out));
    QVERIFY2(shipped.out.contains(QLatin1String("[provisional: shipped dictionary")),
             qPrintable(shipped.out));
}

void TestE2eCheck::aTableOfAnotherFamilyIsRefusedBeforeTheCheck() {
    SimSession session(QStringLiteral("compax3"));
    START_SIM(session);
    const QString file = session.path(QStringLiteral("controller.csv"));
    QVERIFY(writeBytes(file, "position,1,0x1010\n"));
    const CliRun check = session.cli({"check", "--parameters", file});
    QVERIFY2(check.exitCode != 0 && check.exitCode != 1, describe(check).constData());
    // The option names its family (issue 39): refused with the protocol,
    // naming both, before anything is opened.
    QVERIFY2(check.err.contains(QLatin1String("--parameters is an option of the mc1 family")) &&
                 check.err.contains(QLatin1String("--protocol compax3")),
             describe(check).constData());
    // Without a protocol it asks for an MC-1; a broken table is said before
    // the line is opened.
    const QString broken = session.path(QStringLiteral("broken.csv"));
    QVERIFY(writeBytes(broken, "position,nine,0x1010\n"));
    const CliRun refused = runCli({"--port", session.ptyPath(), "check", "--parameters", broken});
    QVERIFY2(refused.err.contains(QLatin1String("was not loaded")), describe(refused).constData());
    QVERIFY2(refused.err.contains(QLatin1String("line 1")), describe(refused).constData());
}

QTEST_GUILESS_MAIN(TestE2eCheck)
#include "tst_e2e_check.moc"
