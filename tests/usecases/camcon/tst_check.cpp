// `check` (issue 29) on the in-process CamCon: every reading held on the
// simulator as it is; on one that lacks a query, that one refuted and
// nothing else; in both, only queries reach the device (counted), and a
// check that tries a command has it kept off the line.
#include "sim_bench.h"

#include "comm/usecases/device_check.h"

#include <QLoggingCategory>
#include <QTest>

#include <algorithm>

using namespace cambench;
using namespace cambench::comm;
using namespace cambench::usecases;
using cambench::tests::SimBench;

class TestCheck : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void everyReadingHeldOnTheSimulator();
    void aQueryTheDeviceLacksIsRefuted();
    void theGateKeepsCommandsOffTheLine();
    void aProvisionalFormatNamesItsReading();
};

void TestCheck::initTestCase() {
    QLoggingCategory::setFilterRules(QStringLiteral("cambench.*.debug=false"));
}

void TestCheck::everyReadingHeldOnTheSimulator() {
    SimBench bench;
    const Result<CheckReport> report = checkDevice(*bench.client);
    QVERIFY2(report.ok(), qPrintable(report.error().message));
    QVERIFY2(!report->anyRefuted(), qPrintable(checkReportText(*report)));
    QVERIFY(report->count(CheckVerdict::Held) > 50);
    QCOMPARE(report->familyId, QStringLiteral("camcon"));
    // Every request sent reached the device, and none was a command.
    QCOMPARE(bench.injections().received().size(), report->requestsSent);
    QCOMPARE(bench.commandsSent(), 0);
    QCOMPARE(report->refusedRequests, 0);
}

void TestCheck::aQueryTheDeviceLacksIsRefuted() {
    SimBench bench;
    bench.device().forgetCommand('?', "GTEMP");
    const Result<CheckReport> report = checkDevice(*bench.client);
    QVERIFY2(report.ok(), qPrintable(report.error().message));
    QCOMPARE(report->count(CheckVerdict::Refuted), 1);
    const auto refutedOne = std::find_if(
        report->results.cbegin(), report->results.cend(),
        [](const CheckResult& result) { return result.verdict == CheckVerdict::Refuted; });
    QCOMPARE(refutedOne->id, QStringLiteral("ascii.?GTEMP"));
    QVERIFY2(refutedOne->observed.contains(QLatin1String(":Z")), qPrintable(refutedOne->observed));
    QCOMPARE(bench.injections().received().size(), report->requestsSent);
    QCOMPARE(bench.commandsSent(), 0);
    const QJsonObject json = checkReportJson(*report);
    QCOMPARE(json.value(QStringLiteral("refuted")).toInt(), 1);
}

void TestCheck::theGateKeepsCommandsOffTheLine() {
    SimBench bench;
    const FamilyCheck* camcon = CheckRegistry::instance().find(QStringLiteral("camcon"));
    QVERIFY(camcon);
    Request command;
    command.label = QStringLiteral("!CA");
    command.message = QByteArrayLiteral("!CA");
    QVERIFY(!camcon->refuses(QStringLiteral("standard"), command).isEmpty());
    Request query;
    query.message = QByteArrayLiteral("?GTEMP");
    QVERIFY(camcon->refuses(QStringLiteral("standard"), query).isEmpty());
    // On the engine: a command tried while the gate is on never leaves.
    bench.link->engine().setRequestGate([camcon](const Request& request) {
        return camcon->refuses(QStringLiteral("standard"), request);
    });
    const Result<Fields> cleared = bench.link->call('!', "CA");
    QVERIFY(!cleared.ok());
    QCOMPARE(cleared.error().kind, ErrorKind::Usage);
    QCOMPARE(bench.link->stats().refusedByGate, 1);
    QCOMPARE(bench.commandsSent(), 0);
    QVERIFY(bench.link->call('?', "GTEMP").ok());
}

// Each guessed format's verdict names its reading (comm/camcon/README.md),
// a confirmed one only its catalogue line.
void TestCheck::aProvisionalFormatNamesItsReading() {
    SimBench bench;
    const Result<CheckReport> report = checkDevice(*bench.client);
    QVERIFY2(report.ok(), qPrintable(report.error().message));
    const auto source = [&](const QString& id) {
        for (const CheckResult& result : report->results)
            if (result.id == id) return result.source;
        return QString();
    };
    QVERIFY2(
        source(QStringLiteral("ascii.?BSPEED")).startsWith(QLatin1String("provisional: P-ASCII-2")),
        qPrintable(source(QStringLiteral("ascii.?BSPEED"))));
    QVERIFY(source(QStringLiteral("ascii.?TZK")).contains(QLatin1String("P-ASCII-6")));
    QVERIFY(source(QStringLiteral("ascii.?GSTYP")).contains(QLatin1String("P-ASCII-8")));
    QCOMPARE(source(QStringLiteral("ascii.?NF")),
             QStringLiteral("comm/camcon/ascii/catalogue.cpp: ?NF"));
    QVERIFY(checkReportText(*report).contains(
        QLatin1String("[provisional: P-ASCII-2, our reading, see comm/camcon/README.md")));
}

QTEST_GUILESS_MAIN(TestCheck)
#include "tst_check.moc"
