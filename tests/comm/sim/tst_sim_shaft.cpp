// Issue 30, item 5: the simulated machine's shaft (comm/sim/sim_shaft.h).
// Its motion on a clock the test drives (a jog, a move to its end, a drive
// that goes away); the port keys shaft=, shaftaxis=, perturn= taken out of
// a "sim:..." port and refused where they do not fit; and two in-process
// ports of one process coupled as the GUI's demo machine couples them: the
// real Compax3 device jogs its simulated drive and the simulated CamCon's
// position turns with it, and holds after the stop.
#include "comm/compax3/compax3_drive.h"
#include "comm/device/family_registry.h"
#include "comm/sim/camcon/sim_camcon_endpoint.h"
#include "comm/sim/camcon/sim_device.h"
#include "comm/sim/sim_shaft.h"
#include "comm/sim/sim_transport.h"
#include "model/machine/machine_file.h"

#include <QFile>

#include <QTest>

#include <map>

using namespace cambench;
using namespace cambench::comm;

namespace {

struct FakeClock {
    qint64 ms = 1000;
    SimShaft::Clock clock() {
        return [this] { return ms; };
    }
};

SerialSettings fastLine() {
    SerialSettings serial;
    serial.baud = 115200;
    return serial;
}

std::unique_ptr<Transport> simPort(const QString& port, const QString& protocol) {
    Result<std::unique_ptr<Transport>> transport = makeSimTransport(port, fastLine(), protocol);
    if (!transport) qWarning("%s", qPrintable(transport.error().message));
    if (!transport) return nullptr;
    (void)(*transport)->open();
    return std::move(transport).value();
}

// The simulated CamCon behind an in-process port: its position as its
// ?IGWG answers it.
qint32 camPosition(Transport& transport) {
    auto& line = static_cast<SimCamConEndpoint&>(static_cast<SimTransport&>(transport).line());
    return line.device(0)->axis().position();
}

QString portError(const QString& port, const QString& protocol) {
    const Result<std::unique_ptr<Transport>> transport =
        makeSimTransport(port, fastLine(), protocol);
    return transport ? QString() : transport.error().message;
}

}  // namespace

class TestSimShaft : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aJogRunsOnUntilItsEndAndAStopHolds() {
        FakeClock time;
        SimShaft shaft(time.clock());
        QCOMPARE(shaft.position(), 0.0);  // no drive yet
        const int drive = shaft.takeDrive();
        shaft.publish(drive, {10.0, 50.0, 1000.0});
        time.ms += 2000;
        QCOMPARE(shaft.position(), 110.0);
        QCOMPARE(shaft.velocity(), 50.0);
        time.ms += 60000;  // far past the end limit
        QCOMPARE(shaft.position(), 1000.0);
        QCOMPARE(shaft.velocity(), 0.0);
        shaft.publish(drive, {400.0, -20.0, 300.0});  // backwards to a target
        time.ms += 1000;
        QCOMPARE(shaft.position(), 380.0);
        shaft.publish(drive, {380.0, 0.0, std::nullopt});  // stopped
        time.ms += 5000;
        QCOMPARE(shaft.position(), 380.0);
    }

    void theDriveConnectedLastDrivesAndOneThatGoesAwayStopsTheShaft() {
        FakeClock time;
        SimShaft shaft(time.clock());
        const int first = shaft.takeDrive();
        shaft.publish(first, {0.0, 10.0, std::nullopt});
        const int second = shaft.takeDrive();              // a reconnected drive
        shaft.publish(first, {500.0, 0.0, std::nullopt});  // the old one: ignored
        shaft.publish(second, {0.0, 100.0, std::nullopt});
        time.ms += 1000;
        QCOMPARE(shaft.position(), 100.0);
        shaft.release(first);  // not the driver: nothing changes
        time.ms += 1000;
        QCOMPARE(shaft.position(), 200.0);
        shaft.release(second);
        time.ms += 1000;
        QCOMPARE(shaft.position(), 200.0);
        QCOMPARE(shaft.velocity(), 0.0);
    }

    void theShaftKeysAreTakenOutOfThePort() {
        const Result<SimPortWithShaft> seat =
            takeSimShaftKeys(QStringLiteral("sim:devices=0;shaft=press;perturn=720"));
        QVERIFY(seat.ok());
        QCOMPARE(seat->port, QStringLiteral("sim:devices=0"));
        QVERIFY(seat->seat && seat->seat->shaft);
        QCOMPARE(seat->seat->perTurn.value_or(0), 720.0);
        QVERIFY(!seat->seat->axis);
        QCOMPARE(takeSimShaftKeys(QStringLiteral("sim:shaft=press"))->port, QStringLiteral("sim"));
        QVERIFY(!takeSimShaftKeys(QStringLiteral("sim:type=S150V4"))->seat);
        // The same name is the same shaft while a device holds it.
        QCOMPARE(takeSimShaftKeys(QStringLiteral("sim:shaft=press"))->seat->shaft,
                 seat->seat->shaft);
        QVERIFY(!takeSimShaftKeys(QStringLiteral("sim:shaft=")).ok());
        QVERIFY(!takeSimShaftKeys(QStringLiteral("sim:shaft=a;perturn=0")).ok());
        QVERIFY(!takeSimShaftKeys(QStringLiteral("sim:shaft=a;shaftaxis=x")).ok());
        QVERIFY(!takeSimShaftKeys(QStringLiteral("sim:perturn=100")).ok());
    }

    void keysThatDoNotFitTheDeviceAreRefused() {
        QVERIFY2(portError("sim:shaft=k1;shaftaxis=2", "standard").contains("shaftaxis="),
                 qPrintable(portError("sim:shaft=k1;shaftaxis=2", "standard")));
        QVERIFY2(portError("sim:shaft=k1;perturn=100", "compax3").contains("perturn="),
                 qPrintable(portError("sim:shaft=k1;perturn=100", "compax3")));
        QVERIFY2(portError("sim:shaft=k1;shaftaxis=2", "compax3").contains("one axis"),
                 qPrintable(portError("sim:shaft=k1;shaftaxis=2", "compax3")));
        QVERIFY2(portError("sim:axes=1,3;shaft=k1;shaftaxis=2", "mc1").contains("no axis 2"),
                 qPrintable(portError("sim:axes=1,3;shaft=k1;shaftaxis=2", "mc1")));
        QVERIFY(portError("sim:axes=1,3;shaft=k1;shaftaxis=3", "mc1").isEmpty());
    }

    // The GUI's demo machine (docs/demo-machine.json): every device on its
    // in-process port, "sim:shaft=demo" on the drive's and on the CamCon's.
    void theDemoMachinesInProcessPortsTurnTheCamsWithTheDrive() {
        QFile file(QStringLiteral(CAMBENCH_DEMO_MACHINE));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const Result<MachineFile> demo = parseMachineFile(file.readAll(), file.fileName());
        QVERIFY2(demo.ok(), qPrintable(demo.error().message));
        std::map<QString, std::unique_ptr<Transport>> ports;
        for (const MachineDevice& device : demo->devices) {
            QString protocol = device.option(QStringLiteral("protocol"));
            if (protocol.isEmpty())
                protocol = FamilyRegistry::instance().find(device.family)->defaultProtocol;
            ports[device.name] = simPort(device.option(QStringLiteral("port")), protocol);
            QVERIFY2(ports[device.name], qPrintable(device.name));
        }
        std::unique_ptr<Transport> cams = std::move(ports[QStringLiteral("cams")]);
        std::unique_ptr<Transport> feed = std::move(ports[QStringLiteral("feed")]);
        std::unique_ptr<Transport> other = simPort(QStringLiteral("sim:shaft=t-other"), "standard");
        QVERIFY(cams && other && feed);
        LineTiming timing;
        timing.baud = 115200;
        Compax3Drive drive(*feed, QStringLiteral("compax3"), -1, 0, timing);
        Compax3Device& device = drive;
        QCOMPARE(camPosition(*cams), 0);
        QVERIFY(device.motion(Compax3Motion::Enable).ok());
        QVERIFY(device.motion(Compax3Motion::JogPlus).ok());
        bool turned = false;
        for (int look = 0; look < 500 && !turned; ++look) {
            QTest::qWait(10);
            turned = camPosition(*cams) > 0;
        }
        QVERIFY(device.motion(Compax3Motion::Stop).ok());
        QVERIFY(turned);
        QCOMPARE(camPosition(*other), 0);  // another shaft

        const Result<Compax3DriveStatus> status = device.status();
        QVERIFY(status.ok());
        const qint32 held = camPosition(*cams);
        QTest::qWait(50);
        QCOMPARE(camPosition(*cams), held);
        QVERIFY2(held == qint32(std::floor(status->position)) % 360 ||
                     held == qint32(std::floor(status->position - 0.001)) % 360,
                 qPrintable(QStringLiteral("cams %1, drive %2").arg(held).arg(status->position)));

        feed.reset();  // the drive goes away: the cams stay where they are
        QCOMPARE(camPosition(*cams), held);
    }
};

QTEST_GUILESS_MAIN(TestSimShaft)
#include "tst_sim_shaft.moc"
