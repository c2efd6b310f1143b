// Issue 30, item 5: `cambench-sim --machine FILE` serves every device of a
// machine file at once, one "NAME PATH" line each, and each answers the real
// cambench-cli as its family does; a mistake in the file is refused naming
// the device before anything is served; the shaft couples a drive's actual
// position (a Compax3's, an MC200 axis's) to the CamCon's: a jog turns the
// cams, a stop holds them, and the CamCon's position is the drive's scaled
// into its 0..359.
#include "e2e_support.h"

#include <QDeadlineTimer>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>
#include <QProcess>
#include <QSet>
#include <QTcpServer>
#include <QTest>

#include <cmath>
#include <memory>
#include <vector>

using namespace cambench::e2e;

namespace {

// JSON written with ' for " (readable here; moc skips a file with raw strings).
QByteArray json(const char* text) {
    return QByteArray(text).replace('\'', '"');
}

// A CamCon, an MC200 and a Compax3 at the fast test rate; `shaft` the
// file's "shaft" entry (may be empty). The ports are left out by the sim.
QByteArray pressFile(const char* shaft = "") {
    return json(
               "{'machine': 'Press 7', 'devices': ["
               "  {'name': 'cams', 'family': 'camcon', 'port': '/dev/ttyUSB0', "
               "   'protocol': 'standard', 'baud': 115200},"
               "  {'name': 'press-plc', 'family': 'mc1', 'port': '/dev/ttyUSB1', "
               "   'variant': 'mc200v2', 'baud': 115200},"
               "  {'name': 'feed', 'family': 'compax3', 'port': 'tcp://press7-ds:4001', "
               "   'baud': 115200}]") +
           json(shaft) + "}";
}

// The real cambench-sim --machine: the "NAME PATH" lines it prints first.
class MachineSim {
public:
    ~MachineSim() {
        if (m_process.state() == QProcess::NotRunning) return;
        m_process.kill();
        m_process.waitForFinished(5000);
    }

    // Starts it and reads `devices` lines; false, with errorText(), when it
    // did not print them.
    bool start(const QStringList& args, int devices) {
        m_process.setProgram(QStringLiteral(CAMBENCH_SIM_EXE));
        m_process.setArguments(args);
        m_process.setStandardErrorFile(QProcess::nullDevice());
        endWithThisTest(m_process);
        m_process.start();
        const QDeadlineTimer deadline(hangBoundMs(20000));
        while (m_order.size() < devices) {
            if (m_process.canReadLine()) {
                const QString line = QString::fromUtf8(m_process.readLine()).trimmed();
                const QString name = line.section(QLatin1Char(' '), 0, 0);
                m_paths.insert(name, line.section(QLatin1Char(' '), 1));
                m_order << name;
                continue;
            }
            if (deadline.hasExpired() || m_process.state() == QProcess::NotRunning) {
                m_error = QStringLiteral("cambench-sim %1 printed %2 of %3 lines")
                              .arg(args.join(u' '))
                              .arg(m_order.size())
                              .arg(devices);
                return false;
            }
            m_process.waitForReadyRead(100);
        }
        return true;
    }

    QString path(const QString& name) const { return m_paths.value(name); }
    QStringList names() const { return m_order; }
    QString errorText() const { return m_error; }

private:
    QProcess m_process;
    QMap<QString, QString> m_paths;
    QStringList m_order;
    QString m_error;
};

// cambench-cli on one device of the machine at the fast rate.
CliRun cliOn(const QString& port, const QStringList& familyArgs, const QStringList& command) {
    return runCli(QStringList{QStringLiteral("--port"), port, QStringLiteral("--baud"), kFastBaud} +
                  familyArgs + command);
}

const QStringList kCamCon{QStringLiteral("--family"), QStringLiteral("camcon")};
const QStringList kMc1{QStringLiteral("--family"), QStringLiteral("mc1"),
                       QStringLiteral("--variant"), QStringLiteral("mc200v2")};
const QStringList kCompax3{QStringLiteral("--family"), QStringLiteral("compax3")};

// The first of `count` consecutive TCP ports that are free now (0: none
// found); a machine's devices take them one after the other.
quint16 freePorts(int count) {
    for (int attempt = 0; attempt < 20; ++attempt) {
        QTcpServer probe;
        if (!probe.listen(QHostAddress::LocalHost, 0)) return 0;
        const quint16 base = probe.serverPort();
        if (base > 65535 - count) continue;
        probe.close();
        std::vector<std::unique_ptr<QTcpServer>> held;
        bool free = true;
        for (int i = 0; i < count && free; ++i) {
            held.push_back(std::make_unique<QTcpServer>());
            free = held.back()->listen(QHostAddress::Any, quint16(base + i));
        }
        if (free) return base;
    }
    return 0;
}

// The number `key` of a --json answer; NaN when it is not there.
double jsonNumber(const CliRun& run, const char* key) {
    const QJsonValue value =
        QJsonDocument::fromJson(run.out.toUtf8()).object().value(QLatin1String(key));
    return value.isDouble() ? value.toDouble() : std::nan("");
}

double camPosition(const MachineSim& sim) {
    return jsonNumber(cliOn(sim.path(QStringLiteral("cams")), kCamCon, {"status", "--json"}),
                      "position");
}

// The CamCon's position for a drive at `drive` units, `perTurn` a turn of
// its 0..359 (the simulator's scaling, sim_axis.cpp).
int scaled(double drive, double perTurn) {
    const auto units = qint64(std::floor(drive / perTurn * 360.0));
    return int(((units % 360) + 360) % 360);
}

}  // namespace

class TestE2eSimMachine : public QObject {
    Q_OBJECT
private Q_SLOTS:
    // One line per device in the file's order, each a pty that answers as
    // its family: the CamCon its EPROM date, the MC200 its variant, the
    // Compax3 its info string.
    void servesEveryDeviceOnItsOwnPty() {
        SimSession scratch;
        const QString file = scratch.path(QStringLiteral("press7.json"));
        QVERIFY(writeBytes(file, pressFile()));
        MachineSim sim;
        QVERIFY2(sim.start({"--machine", file}, 3), qPrintable(sim.errorText()));
        QCOMPARE(sim.names(), QStringList({"cams", "press-plc", "feed"}));
        QVERIFY(sim.path("cams") != sim.path("feed"));

        const CliRun cams = cliOn(sim.path("cams"), kCamCon, {"info"});
        VERIFY_EXIT(cams, 0);
        QVERIFY2(cams.out.contains(QLatin1String("11.10.1994")), qPrintable(cams.out));
        const CliRun plc = cliOn(sim.path("press-plc"), kMc1, {"mc", "info"});
        VERIFY_EXIT(plc, 0);
        QVERIFY2(plc.out.contains(QLatin1String("MC200")), qPrintable(plc.out));
        const CliRun feed = cliOn(sim.path("feed"), kCompax3, {"c3", "info"});
        VERIFY_EXIT(feed, 0);
        QVERIFY2(feed.out.contains(QLatin1String("S025V2")), qPrintable(feed.out));
    }

    // The demo machine the desktop application opens (its in-process
    // ports left out here) is served as it is.
    void servesTheDemoMachine() {
        MachineSim sim;
        QVERIFY2(sim.start({"--machine", CAMBENCH_DEMO_MACHINE}, 3), qPrintable(sim.errorText()));
        QCOMPARE(sim.names(), QStringList({"cams", "press-plc", "feed"}));
        const CliRun cams = runCli({"--port", sim.path("cams"), "status", "--json"});
        VERIFY_EXIT(cams, 0);
        QCOMPARE(jsonNumber(cams, "position"), 0.0);  // on the feed's shaft, standing
    }

    // --tcp BASE: the devices on BASE, BASE+1, BASE+2 in the file's order,
    // "NAME tcp://127.0.0.1:PORT"; each answers there.
    void servesEveryDeviceOnItsOwnTcpPort() {
        SimSession scratch;
        const QString file = scratch.path(QStringLiteral("press7.json"));
        QVERIFY(writeBytes(file, pressFile()));
        const quint16 base = freePorts(3);
        QVERIFY(base != 0);
        MachineSim sim;
        QVERIFY2(sim.start({"--machine", file, "--tcp", QString::number(base)}, 3),
                 qPrintable(sim.errorText()));
        for (int i = 0; i < 3; ++i)
            QCOMPARE(sim.path(sim.names().at(i)),
                     QStringLiteral("tcp://127.0.0.1:%1").arg(base + i));
        const CliRun feed = cliOn(sim.path("feed"), kCompax3, {"c3", "info"});
        VERIFY_EXIT(feed, 0);
        QVERIFY2(feed.out.contains(QLatin1String("S025V2")), qPrintable(feed.out));
        const CliRun cams = cliOn(sim.path("cams"), kCamCon, {"info"});
        VERIFY_EXIT(cams, 0);
    }

    // --tcp 0: each on a free port of its own.
    void tcpZeroTakesFreePorts() {
        SimSession scratch;
        const QString file = scratch.path(QStringLiteral("press7.json"));
        QVERIFY(writeBytes(file, pressFile()));
        MachineSim sim;
        QVERIFY2(sim.start({"--machine", file, "--tcp", "0"}, 3), qPrintable(sim.errorText()));
        QCOMPARE(QSet<QString>({sim.path("cams"), sim.path("press-plc"), sim.path("feed")}).size(),
                 3);
        VERIFY_EXIT(cliOn(sim.path("press-plc"), kMc1, {"mc", "info"}), 0);
    }

    // Each kind of mistake: exit 2, the device named, nothing served.
    void mistakesAreRefusedNamingTheDevice_data() {
        QTest::addColumn<QByteArray>("file");
        QTest::addColumn<QString>("named");
        QTest::newRow("wrong key") << json(
                                          "{'machine': 'M', 'devices': ["
                                          "{'name': 'cams', 'family': 'camcon', 'port': 'p'},"
                                          "{'name': 'feed', 'family': 'compax3', 'port': 'p', "
                                          "'colour': 'red'}]}")
                                   << QStringLiteral("device 2 (feed)");
        QTest::newRow("unknown family") << json(
                                               "{'machine': 'M', 'devices': ["
                                               "{'name': 'cams', 'family': 'camcon', 'port': 'p'},"
                                               "{'name': 'saw', 'family': 'lathe', 'port': 'p'}]}")
                                        << QStringLiteral("device 2 (saw)");
        QTest::newRow("option its simulator lacks")
            << json(
                   "{'machine': 'M', 'devices': ["
                   "{'name': 'cams', 'family': 'camcon', 'port': 'p', 'variant': 'mc200v2'}]}")
            << QStringLiteral("device 1 (cams)");
        QTest::newRow("protocol of another family")
            << json(
                   "{'machine': 'M', 'devices': ["
                   "{'name': 'cams', 'family': 'camcon', 'port': 'p'},"
                   "{'name': 'feed', 'family': 'compax3', 'port': 'p', 'protocol': 'standard'}]}")
            << QStringLiteral("device 2 (feed)");
        QTest::newRow("bad value") << json(
                                          "{'machine': 'M', 'devices': ["
                                          "{'name': 'plc', 'family': 'mc1', 'port': 'p', "
                                          "'variant': 'mc999'}]}")
                                   << QStringLiteral("device 1 (plc)");
        QTest::newRow("shaft from a CamCon")
            << json(
                   "{'machine': 'M', 'devices': ["
                   "{'name': 'cams', 'family': 'camcon', 'port': 'p'},"
                   "{'name': 'feed', 'family': 'compax3', 'port': 'p'}],"
                   "'shaft': {'from': 'cams', 'to': 'feed'}}")
            << QStringLiteral("device 1 (cams) cannot drive a shaft");
        QTest::newRow("shaft axis the drive lacks")
            << json(
                   "{'machine': 'M', 'devices': ["
                   "{'name': 'cams', 'family': 'camcon', 'port': 'p'},"
                   "{'name': 'feed', 'family': 'compax3', 'port': 'p'}],"
                   "'shaft': {'from': 'feed', 'to': 'cams', 'axis': 2}}")
            << QStringLiteral("device 2 (feed)");
    }
    void mistakesAreRefusedNamingTheDevice() {
        QFETCH(QByteArray, file);
        QFETCH(QString, named);
        SimSession scratch;
        const QString path = scratch.path(QStringLiteral("bad.json"));
        QVERIFY(writeBytes(path, file));
        const CliRun run = runProgram(QStringLiteral(CAMBENCH_SIM_EXE), {"--machine", path}, 20000);
        VERIFY_EXIT(run, 2);
        QVERIFY2(run.err.contains(named), qPrintable(run.err));
        QVERIFY2(run.out.isEmpty(), qPrintable(run.out));  // nothing was served
    }

    // The shaft from the Compax3: standing, the CamCon does not turn on its
    // own; a jog turns it; after the stop it holds, at the drive's
    // position scaled one unit to one (360 a turn, the default).
    void compax3JogTurnsTheCamsAndAStopHoldsThem() {
        SimSession scratch;
        const QString file = scratch.path(QStringLiteral("press7.json"));
        QVERIFY(writeBytes(file, pressFile(", 'shaft': {'from': 'feed', 'to': 'cams'}")));
        MachineSim sim;
        QVERIFY2(sim.start({"--machine", file}, 3), qPrintable(sim.errorText()));
        const QString feed = sim.path("feed");
        QCOMPARE(camPosition(sim), 0.0);
        QCOMPARE(camPosition(sim), 0.0);  // its own motion yields to the shaft

        VERIFY_EXIT(cliOn(feed, kCompax3, {"c3", "enable"}), 0);
        VERIFY_EXIT(cliOn(feed, kCompax3, {"c3", "jog", "+"}), 0);
        // Turning: a bounded number of looks, no clock.
        bool turned = false;
        for (int look = 0; look < 50 && !turned; ++look) turned = camPosition(sim) > 0.0;
        const CliRun stop = cliOn(feed, kCompax3, {"c3", "stop"});
        VERIFY_EXIT(stop, 0);
        QVERIFY(turned);

        const double drive =
            jsonNumber(cliOn(feed, kCompax3, {"c3", "status", "--json"}), "position");
        QVERIFY(drive > 0.0);
        const double held = camPosition(sim);
        QCOMPARE(camPosition(sim), held);
        // The drive answers to 0.001: either side of a whole unit.
        QVERIFY2(held == scaled(drive, 360.0) || held == scaled(drive - 0.001, 360.0),
                 qPrintable(QStringLiteral("cams %1, drive %2").arg(held).arg(drive)));
    }

    // The shaft from an MC200's axis 2, 1000 units a turn: the other axis
    // does not move it; axis 2's jog does; its stop holds it.
    void mc1AxisJogTurnsTheCamsScaledByPerTurn() {
        SimSession scratch;
        const QString file = scratch.path(QStringLiteral("press7.json"));
        QVERIFY(writeBytes(file, pressFile(", 'shaft': {'from': 'press-plc', 'to': 'cams', "
                                           "'axis': 2, 'per-turn': 1000}")));
        MachineSim sim;
        QVERIFY2(sim.start({"--machine", file}, 3), qPrintable(sim.errorText()));
        const QString plc = sim.path("press-plc");
        VERIFY_EXIT(cliOn(plc, kMc1, {"mc", "axis", "1", "move", "--rel", "500"}), 0);
        QCOMPARE(camPosition(sim), 0.0);

        VERIFY_EXIT(cliOn(plc, kMc1, {"mc", "axis", "2", "jog", "+"}), 0);
        bool turned = false;
        for (int look = 0; look < 50 && !turned; ++look) turned = camPosition(sim) > 0.0;
        VERIFY_EXIT(cliOn(plc, kMc1, {"mc", "axis", "2", "stop"}), 0);
        QVERIFY(turned);

        const double axis =
            jsonNumber(cliOn(plc, kMc1, {"mc", "axis", "2", "status", "--json"}), "position");
        QVERIFY(axis > 0.0);
        const double held = camPosition(sim);
        QCOMPARE(camPosition(sim), held);
        // The controller answers whole units: within half a unit of it.
        QVERIFY2(held == scaled(axis - 0.5, 1000.0) || held == scaled(axis + 0.49, 1000.0),
                 qPrintable(QStringLiteral("cams %1, axis %2").arg(held).arg(axis)));
    }
};

QTEST_GUILESS_MAIN(TestE2eSimMachine)
#include "tst_e2e_sim_machine.moc"
