// Issue 16: a CamCon over the Cam-BUS through the real request engine and
// framing backend, on the in-process simulated bus (real time): every ASCII
// operation reaches the device asked, the scan names every user, and with 1 %
// damaged blocks and 1 % lost acknowledgements a backup and a program read
// are exactly what the device holds, while the display keeps being answered.
#include "comm/camcon/cambus/cambus_camcon.h"
#include "comm/sim/camcon/cambus/sim_cambus_line.h"
#include "comm/sim/camcon/sim_demo.h"
#include "comm/sim/camcon/sim_port_config.h"
#include "comm/sim/sim_transport.h"

#include <QTest>

using namespace cambench;
using namespace cambench::comm;

namespace {

// Devices 3 and 7, display 12 polling 3, the PC 63 talking to 3.
struct BusBench {
    explicit BusBench(double damage = 0, double loseAck = 0) {
        SimPortConfig config;
        config.devices = {3, 7};
        config.displays = {12};
        config.baud = 38400;
        config.faults.corruptProbability = damage;
        config.faults.dropProbability = loseAck;
        config.faults.seed = 11;
        applySimProtocol(config, QStringLiteral("cambus"));
        SimulatedLine simulated{makeSimEndpoint(config), SimPacer(38400, true, 10),
                                QStringLiteral("simulated Cam-BUS")};
        line = static_cast<SimCamBusLine*>(simulated.endpoint.get());
        transport = std::make_unique<SimTransport>(std::move(simulated));
        [[maybe_unused]] const Status opened = transport->open();
        AsciiSettings ascii;
        ascii.device = 3;
        LineTiming timing;
        timing.baud = 38400;
        monitor = std::make_shared<CamBusMonitor>();
        camCon = std::make_unique<CamBusCamCon>(*transport, ascii, timing, CamBusStationConfig{},
                                                monitor);
    }

    // What the simulated device's EEPROM holds now, block by block.
    QList<EepromBlock> deviceEeprom(int number) {
        SimDevice& device = *line->device(number);
        QList<EepromBlock> blocks;
        for (int block = 0;; ++block) {
            const std::optional<QByteArray> data = device.eeprom().read(block, device.state());
            if (!data) break;
            blocks << EepromBlock{quint16(block), *data};
        }
        return blocks;
    }

    SimCamBusLine* line = nullptr;
    std::unique_ptr<SimTransport> transport;
    CamBusMonitorPtr monitor;
    std::unique_ptr<CamBusCamCon> camCon;
};

}  // namespace

class TestCamBusCamCon : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void everyOperationReachesTheDeviceAsked() {
        BusBench bench;
        const Result<DeviceInfo> three = bench.camCon->readInfo();
        QVERIFY2(three.ok(), three ? "" : qPrintable(three.error().message));
        QCOMPARE(three->deviceNumber, 3);
        QCOMPARE(bench.camCon->protocolId(), QStringLiteral("cambus"));
        bench.camCon->setDevice(7);
        const Result<DeviceInfo> seven = bench.camCon->readInfo();
        QVERIFY(seven.ok());
        QCOMPARE(seven->deviceNumber, 7);
        // A write goes to 7 only.
        const Track track{4, {{10, 20}, {100, 150}}};
        const Status written = bench.camCon->writeTrack(1, track);
        QVERIFY2(written.ok(), written ? "" : qPrintable(written.error().message));
        const Result<Track> back = bench.camCon->readTrack(1, 4);
        QVERIFY(back.ok());
        QCOMPARE(*back, track);
        bench.camCon->setDevice(3);
        const Result<Track> other = bench.camCon->readTrack(1, 4);
        QVERIFY(other.ok());
        QVERIFY(!(*other == track));
        // The bus view the GUI reads holds the users the PC heard.
        CamBusView view;
        QVERIFY(bench.monitor->read(view));
        QCOMPARE(view.users.keys(), QList<int>({3, 7, 12, 63}));
        QVERIFY(bench.line->display()->answers() > 0);
    }

    void theScanNamesEveryUser() {
        BusBench bench;
        const Result<BusUsers> users = bench.camCon->scanUsers();
        QVERIFY2(users.ok(), users ? "" : qPrintable(users.error().message));
        QVERIFY(users->kindsKnown);
        QList<std::pair<int, BusUser::Kind>> got;
        for (const BusUser& user : users->users) got << std::make_pair(user.number, user.kind);
        const QList<std::pair<int, BusUser::Kind>> expected{{3, BusUser::CamCon},
                                                            {7, BusUser::CamCon},
                                                            {12, BusUser::Other},
                                                            {63, BusUser::ThisPc}};
        QCOMPARE(got, expected);
        const Result<QList<int>> camCons = bench.camCon->scanBus(0, 63);
        QCOMPARE(*camCons, QList<int>({3, 7}));
    }

    void anAbsentDeviceIsNotExecutedAndSaysSo() {
        BusBench bench;
        QVERIFY(bench.camCon->readInfo().ok());
        bench.camCon->setDevice(5);
        const Result<DeviceInfo> info = bench.camCon->readInfo();
        QVERIFY(!info.ok());
        QVERIFY2(info.error().message.contains(QLatin1String("device 5 did not take the request")),
                 qPrintable(info.error().message));
        QVERIFY(info.error().message.contains(QLatin1String("it was not executed")));
    }

    void aQueueThatStaysFullIsSaid() {
        BusBench bench;
        QVERIFY(bench.camCon->readInfo().ok());
        bench.line->camCon(3)->station().setRoomCheck([] { return false; });
        bench.camCon->link().setRetries(0);  // one attempt: 10 s of refusals
        const Result<QByteArray> reply = bench.camCon->raw("?GNR");
        QVERIFY(!reply.ok());
        QVERIFY2(reply.error().message.contains(QLatin1String("receive queue stayed full")),
                 qPrintable(reply.error().message));
        QVERIFY(reply.error().message.contains(QLatin1String("was not sent")));
    }

    void backupAndProgramReadAreExactAtOnePercentFaults() {
        BusBench bench(0.01, 0.01);
        const Result<EepromImage> image = bench.camCon->backup();
        QVERIFY2(image.ok(), image ? "" : qPrintable(image.error().message));
        QCOMPARE(image->blocks, bench.deviceEeprom(3));
        const Result<CamProgram> program = bench.camCon->readProgram(0, 32);
        QVERIFY(program.ok());
        BusBench clean;
        QCOMPARE(*program, *clean.camCon->readProgram(0, 32));
        const SimCamBusMedium::Counters& faults = bench.line->medium().counters();
        qInfo() << faults.damagedBlocks << "blocks damaged," << faults.lostAcks
                << "acknowledgements lost; display answers:" << bench.line->display()->answers()
                << "longest pause" << bench.line->display()->longestPauseMs() << "ms";
        QVERIFY(faults.damagedBlocks + faults.lostAcks > 0);
        QVERIFY(bench.line->display()->longestPauseMs() < 1500);
    }
};

QTEST_GUILESS_MAIN(TestCamBusCamCon)
#include "tst_cambus_camcon.moc"
