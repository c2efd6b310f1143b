// The simulator's 3964R line with each link fault on its own, in process:
// every kind happens, and the table interface still gets the right data.
#include "comm/camcon/table/table_camcon.h"
#include "comm/device/protocol_registry.h"
#include "comm/sim/camcon/camcon_simulator.h"
#include "comm/sim/camcon/table/sim_table_line.h"
#include "comm/sim/sim_transport.h"

#include <QLoggingCategory>
#include <QTest>

using namespace cambench;
using namespace cambench::comm;

namespace {

using Counter = int SimTableLine::Counters::*;

}  // namespace

class TestSimTableLine : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { QLoggingCategory::setFilterRules(QStringLiteral("cambench.*=false")); }
    void eachLinkFaultHappensAndResultsStayRight_data();
    void eachLinkFaultHappensAndResultsStayRight();
    void deadDeviceEndsInOneClearFailure();
};

void TestSimTableLine::eachLinkFaultHappensAndResultsStayRight_data() {
    QTest::addColumn<QString>("fault");
    QTest::addColumn<Counter>("counter");
    QTest::newRow("nak") << QStringLiteral("nak") << &SimTableLine::Counters::naks;
    QTest::newRow("lost DLE") << QStringLiteral("lostdle") << &SimTableLine::Counters::lostDles;
    QTest::newRow("corrupt BCC") << QStringLiteral("corrupt")
                                 << &SimTableLine::Counters::corruptBccs;
    QTest::newRow("collision") << QStringLiteral("collision")
                               << &SimTableLine::Counters::collisions;
    QTest::newRow("lost reply") << QStringLiteral("drop")
                                << &SimTableLine::Counters::droppedReplies;
}

void TestSimTableLine::eachLinkFaultHappensAndResultsStayRight() {
    QFETCH(QString, fault);
    QFETCH(Counter, counter);
    const SerialSettings serial;
    Result<std::unique_ptr<Transport>> made =
        makeCamConSimTransport(QStringLiteral("sim:throttle=0;seed=5;%1=0.1").arg(fault), serial,
                               QStringLiteral("3964r-n96"));
    QVERIFY(made);
    std::unique_ptr<Transport> transport = std::move(made).value();
    QVERIFY(transport->open());
    table::TableCamCon device(*transport, {}, lineTimingFor(serial));
    for (int output = 1; output <= 8; ++output) {
        const Track track{output, {{qint32(10 * output), qint32(10 * output + 5)}, {300, 5}}};
        const Status written = device.writeTrack(4, track);
        QVERIFY2(written.ok(), qPrintable(written.error().message));
        const Result<Track> read = device.readTrack(4, output);
        QVERIFY2(read.ok(), qPrintable(read.error().message));
        QCOMPARE(read->cams, (QList<Cam>{track.cams.at(0), track.cams.at(1)}));
    }
    const auto& line = dynamic_cast<SimTransport&>(*transport).line();
    const auto& counters = dynamic_cast<const SimTableLine&>(line).counters();
    QVERIFY2(counters.*counter > 0, qPrintable(fault));
}

void TestSimTableLine::deadDeviceEndsInOneClearFailure() {
    const SerialSettings serial;
    Result<std::unique_ptr<Transport>> made = makeCamConSimTransport(
        QStringLiteral("sim:throttle=0;dead=1"), serial, QStringLiteral("3964r-e38"));
    QVERIFY(made);
    std::unique_ptr<Transport> transport = std::move(made).value();
    QVERIFY(transport->open());
    table::TableCamCon device(*transport, {}, lineTimingFor(serial));
    const Result<DeviceInfo> info = device.readInfo();
    QVERIFY(!info.ok());
    QCOMPARE(info.error().kind, ErrorKind::Communication);
    QVERIFY2(info.error().message.contains(QLatin1String("6 attempts")),
             qPrintable(info.error().message));
    QVERIFY2(info.error().message.contains(QLatin1String("Ser:")),
             qPrintable(info.error().message));
    // The link tried six times once, not six times per engine attempt.
    QCOMPARE(device.engine().lastAttempts(), 4);
}

QTEST_GUILESS_MAIN(TestSimTableLine)
#include "tst_sim_table_line.moc"
