// cambench-sim: a simulated CamCon on a pseudo-terminal (default) or a TCP
// port, for the tool, its tests and demos without hardware.

#include "app/registry/builtin_registry.h"
#include "cambench_version.h"
#include "signal_quitter.h"

#include "comm/camcon/table/rk512.h"
#include "comm/device/family_registry.h"
#include "comm/sim/sim_demo.h"
#include "comm/sim/sim_line.h"
#include "comm/sim/sim_pacer.h"
#include "comm/sim/sim_port_config.h"
#include "comm/sim/sim_pty_server.h"
#include "comm/sim/sim_tcp_server.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QLoggingCategory>
#include <QTextStream>

#include <cstdio>
#include <memory>
#include <optional>

using namespace cambench;
using namespace cambench::comm;

namespace {

constexpr int kStandardBaud = 9600;
constexpr int kMultiuserBaud = 38400;

struct Options {
    SimPortConfig config;
    std::optional<int> pcNumber;
    std::optional<quint16> tcpPort;
    bool verbose = false;
};

int fail(const QString& message) {
    QTextStream(stderr) << "cambench-sim: " << message << Qt::endl;
    return 2;
}

std::optional<double> probability(const QString& text) {
    bool ok = false;
    const double p = text.toDouble(&ok);
    if (!ok || p < 0.0 || p > 1.0) return std::nullopt;
    return p;
}

// Empty on success, else what is wrong.
QString readOptions(const QCommandLineParser& parser, Options& options) {
    SimPortConfig& config = options.config;
    // Only the CamCon is simulated so far; another family is named and refused.
    if (parser.isSet(QStringLiteral("family"))) {
        const Result<const FamilyInfo*> family =
            FamilyRegistry::instance().usable(parser.value(QStringLiteral("family")));
        if (!family) return family.error().message + QLatin1Char('.');
    }
    if (parser.isSet(QStringLiteral("protocol"))) {
        const QString protocol = parser.value(QStringLiteral("protocol"));
        if (!applySimProtocol(config, protocol)) {
            return QStringLiteral(
                       "--protocol must be standard, multiuser, 3964r-n96 or 3964r-e38, not "
                       "\"%1\".")
                .arg(protocol);
        }
    }
    if (parser.isSet(QStringLiteral("devices"))) {
        Result<QList<int>> devices = parseDeviceList(parser.value(QStringLiteral("devices")));
        if (!devices) return QStringLiteral("--devices: %1").arg(devices.error().message);
        config.devices = *devices;
    }
    if (config.tableVariant && config.devices.size() > 1)
        return QStringLiteral("3964R is point to point: one device.");
    if (!config.tableVariant && config.effectiveFraming() == Framing::Standard &&
        config.devices.size() > 1) {
        return QStringLiteral("Standard framing has one device; add --protocol multiuser.");
    }
    bool ok = true;
    config.baud = config.effectiveFraming() == Framing::Multiuser ? kMultiuserBaud : kStandardBaud;
    if (config.tableVariant) config.baud = table::rk512VariantInfo(*config.tableVariant).baudRate;
    if (parser.isSet(QStringLiteral("baud")))
        config.baud = parser.value(QStringLiteral("baud")).toInt(&ok);
    if (!ok || config.baud < 300) return QStringLiteral("--baud needs a baud rate of 300 or more.");
    if (parser.isSet(QStringLiteral("pc-number"))) {
        const int pc = parser.value(QStringLiteral("pc-number")).toInt(&ok);
        if (!ok || pc < 0 || pc > 63) return QStringLiteral("--pc-number needs a number 0..63.");
        options.pcNumber = pc;
    }
    if (parser.isSet(QStringLiteral("tcp"))) {
        const uint port = parser.value(QStringLiteral("tcp")).toUInt(&ok);
        if (!ok || port > 65535) return QStringLiteral("--tcp needs a port number 0..65535.");
        options.tcpPort = quint16(port);
    }
    SimFaultSettings& faults = config.faults;
    const QList<std::pair<const char*, QList<double*>>> probabilities{
        {"corrupt", {&faults.corruptProbability}},
        {"drop", {&faults.dropProbability}},
        {"ignore", {&faults.ignoreProbability}},
        {"nak", {&faults.nakProbability}},
        {"lost-dle", {&faults.lostDleProbability}},
        {"collision", {&faults.collisionProbability}},
        {"link-faults",
         {&faults.corruptProbability, &faults.nakProbability, &faults.lostDleProbability,
          &faults.collisionProbability}},
    };
    for (const auto& [name, targets] : probabilities) {
        if (!parser.isSet(QLatin1String(name))) continue;
        const auto p = probability(parser.value(QLatin1String(name)));
        if (!p) return QStringLiteral("--%1 needs a probability 0..1.").arg(QLatin1String(name));
        for (double* target : targets) *target = *p;
    }
    if (parser.isSet(QStringLiteral("drop-first")))
        config.faults.dropFirstReplyTo = parser.value(QStringLiteral("drop-first")).toLatin1();
    for (const char* name : {"delay", "fill", "users"}) {
        if (!parser.isSet(QLatin1String(name))) continue;
        const int n = parser.value(QLatin1String(name)).toInt(&ok);
        if (!ok || n < 0)
            return QStringLiteral("--%1 needs a whole number of 0 or more.")
                .arg(QLatin1String(name));
        (QByteArray(name) == "delay"  ? config.faults.extraDelayMs
         : QByteArray(name) == "fill" ? config.fill
                                      : config.users) = n;
    }
    if (parser.isSet(QStringLiteral("seed"))) {
        config.faults.seed = parser.value(QStringLiteral("seed")).toUInt(&ok);
        if (!ok) return QStringLiteral("--seed needs a whole number.");
    }
    config.throttle = !parser.isSet(QStringLiteral("no-throttle"));
    config.faults.dead = parser.isSet(QStringLiteral("dead"));
    if (parser.isSet(QStringLiteral("dead-devices"))) {
        Result<QList<int>> dead = parseDeviceList(parser.value(QStringLiteral("dead-devices")));
        if (!dead) return QStringLiteral("--dead-devices: %1").arg(dead.error().message);
        config.deadDevices = *dead;
    }
    options.verbose = parser.isSet(QStringLiteral("verbose"));
    return {};
}

void addOptions(QCommandLineParser& parser) {
    parser.setApplicationDescription(QStringLiteral(
        "Simulated CamCon cam controller. Without --tcp it serves a pseudo-terminal and prints its "
        "path as the first line on stdout."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addOptions({
        {QStringLiteral("family"),
         QStringLiteral("camcon (default); mc1 and compax3 are announced, not built yet."),
         QStringLiteral("family")},
        {QStringLiteral("protocol"),
         QStringLiteral("standard, multiuser, 3964r-n96 or 3964r-e38 (default: multiuser for "
                        "several devices, else standard)."),
         QStringLiteral("protocol")},
        {QStringLiteral("devices"), QStringLiteral("Device numbers 0..63, e.g. 0,5 (default 0)."),
         QStringLiteral("list")},
        {QStringLiteral("baud"),
         QStringLiteral("Baud rate for the timing (default 9600, Multiuser and 3964r-e38 "
                        "38400)."),
         QStringLiteral("rate")},
        {QStringLiteral("pc-number"),
         QStringLiteral("Multiuser: answer only this PC number (default any)."),
         QStringLiteral("n")},
        {QStringLiteral("tcp"),
         QStringLiteral("Serve TCP on this port instead of a pseudo-terminal."),
         QStringLiteral("port")},
        {QStringLiteral("corrupt"), QStringLiteral("Probability of a corrupted reply byte."),
         QStringLiteral("p")},
        {QStringLiteral("drop"),
         QStringLiteral("Probability of a lost reply (the request was executed)."),
         QStringLiteral("p")},
        {QStringLiteral("nak"),
         QStringLiteral("3964R: probability of a NAK to a good block (not executed)."),
         QStringLiteral("p")},
        {QStringLiteral("lost-dle"),
         QStringLiteral("3964R: probability of a DLE of the device lost on the line."),
         QStringLiteral("p")},
        {QStringLiteral("collision"),
         QStringLiteral("3964R: probability of the device's STX crossing the PC's."),
         QStringLiteral("p")},
        {QStringLiteral("link-faults"),
         QStringLiteral("3964R: --corrupt (the reply's BCC), --nak, --lost-dle and --collision "
                        "at once."),
         QStringLiteral("p")},
        {QStringLiteral("ignore"),
         QStringLiteral("Probability of a lost request (not executed, as if damaged)."),
         QStringLiteral("p")},
        {QStringLiteral("drop-first"),
         QStringLiteral("Lose the first reply to a request that starts so, e.g. !EE0000."),
         QStringLiteral("request")},
        {QStringLiteral("delay"), QStringLiteral("Extra delay before every reply."),
         QStringLiteral("ms")},
        {QStringLiteral("seed"), QStringLiteral("Seed of the fault generator (default 1)."),
         QStringLiteral("n")},
        {QStringLiteral("no-throttle"),
         QStringLiteral("Send replies at once instead of at the baud rate.")},
        {QStringLiteral("fill"),
         QStringLiteral("Benchmark state: n cams on every output of every program."),
         QStringLiteral("n")},
        {QStringLiteral("users"),
         QStringLiteral("n users \"User 01\", \"User 02\", ... instead of the demo's two "
                        "(at most 32)."),
         QStringLiteral("n")},
        {QStringLiteral("dead"), QStringLiteral("Never answer.")},
        {QStringLiteral("dead-devices"),
         QStringLiteral("These devices of the line never answer, e.g. 5 (the others do)."),
         QStringLiteral("list")},
        {QStringLiteral("verbose"), QStringLiteral("Log requests to stderr.")},
    });
}

}  // namespace

int main(int argc, char* argv[]) {
    cambench::registerBuiltins();
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("cambench-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(CAMBENCH_VERSION_TEXT));
    QCommandLineParser parser;
    addOptions(parser);
    parser.process(app);
    Options options;
    if (const QString problem = readOptions(parser, options); !problem.isEmpty())
        return fail(problem);
    QLoggingCategory::setFilterRules(
        options.verbose
            ? QStringLiteral("cambench.comm.sim.debug=true")
            : QStringLiteral("cambench.comm.sim.debug=false\ncambench.comm.sim.info=false"));

    std::unique_ptr<SimEndpoint> line = makeSimEndpoint(options.config);
    if (auto* ascii = dynamic_cast<SimLine*>(line.get())) ascii->setPcNumber(options.pcNumber);
    const SimPacer pacer(options.config.baud, options.config.throttle,
                         options.config.bitsPerByte());
    SignalQuitter quitter;
    if (!quitter.isValid()) return fail(QStringLiteral("cannot watch for SIGTERM/SIGINT."));

    std::unique_ptr<QObject> server;
    if (options.tcpPort) {
        auto tcp = std::make_unique<SimTcpServer>(*line, pacer);
        if (const Status listening = tcp->listen(*options.tcpPort); !listening)
            return fail(listening.error().message);
        std::printf("tcp://127.0.0.1:%u\n", unsigned(tcp->port()));
        server = std::move(tcp);
    } else {
        auto pty = std::make_unique<SimPtyServer>(*line, pacer);
        if (const Status opened = pty->open(); !opened) return fail(opened.error().message);
        std::printf("%s\n", qPrintable(pty->slavePath()));
        server = std::move(pty);
    }
    std::fflush(stdout);
    const int code = app.exec();
    server.reset();  // before the line it serves
    return code;
}
