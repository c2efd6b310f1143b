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

QTEST_GUILESS_MAIN(TestE2eCheck)
#include "tst_e2e_check.moc"
