// cambench-sim: a simulated device of any registered family on a
// pseudo-terminal (default) or a TCP port, for the tool, its tests and
// demos without hardware. The options every family shares (protocol,
// faults, pacing, where to serve) are read here; the family's simulator
// reads its own.

#include "app/registry/builtin_registry.h"
#include "app/registry/family_parts.h"
#include "cambench_version.h"
#include "signal_quitter.h"

#include "comm/device/family_registry.h"
#include "comm/device/protocol_registry.h"
#include "comm/sim/sim_pty_server.h"
#include "comm/sim/sim_tcp_server.h"
#include "comm/sim/simulator_registry.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QLoggingCategory>
#include <QSet>
#include <QTextStream>

#include <cstdio>
#include <memory>
#include <optional>

using namespace cambench;
using namespace cambench::comm;

namespace {

struct Options {
    const SimulatorInfo* simulator = nullptr;
    SimHostOptions shared;
    std::optional<quint16> tcpPort;
    bool verbose = false;
};

int fail(const QString& message) {
    QTextStream(stderr) << "cambench-sim: " << message << Qt::endl;
    return 2;
}

// The family's simulator: --family, else the family of --protocol, else the
// default family (the first registered).
QString chooseSimulator(const QCommandLineParser& parser, Options& options) {
    const FamilyRegistry& families = FamilyRegistry::instance();
    QString familyId = families.all().value(0) ? families.all().value(0)->id : QString();
    const QString protocol = parser.value(QStringLiteral("protocol"));
    if (parser.isSet(QStringLiteral("family"))) {
        const Result<const FamilyInfo*> family =
            families.usable(parser.value(QStringLiteral("family")));
        if (!family) return family.error().message + QLatin1Char('.');
        familyId = (*family)->id;
    } else if (const ProtocolInfo* info = ProtocolRegistry::instance().find(protocol)) {
        familyId = info->familyId;
    }
    options.simulator = SimulatorRegistry::instance().find(familyId);
    if (!options.simulator)
        return QStringLiteral("no simulator of family %1 is built into this CamBench.")
            .arg(familyId);
    options.shared.protocol = protocol;
    return {};
}

// Empty on success, else what is wrong.
QString readSharedOptions(const QCommandLineParser& parser, Options& options) {
    bool ok = true;
    if (parser.isSet(QStringLiteral("tcp"))) {
        const uint port = parser.value(QStringLiteral("tcp")).toUInt(&ok);
        if (!ok || port > 65535) return QStringLiteral("--tcp needs a port number 0..65535.");
        options.tcpPort = quint16(port);
    }
    SimFaultSettings& faults = options.shared.faults;
    const QList<std::pair<const char*, double*>> probabilities{
        {"corrupt", &faults.corruptProbability},
        {"drop", &faults.dropProbability},
        {"ignore", &faults.ignoreProbability},
    };
    for (const auto& [name, target] : probabilities) {
        if (!parser.isSet(QLatin1String(name))) continue;
        const auto p = parseProbability(parser.value(QLatin1String(name)));
        if (!p) return QStringLiteral("--%1 needs a probability 0..1.").arg(QLatin1String(name));
        *target = *p;
    }
    if (parser.isSet(QStringLiteral("drop-first")))
        faults.dropFirstReplyTo = parser.value(QStringLiteral("drop-first")).toLatin1();
    if (parser.isSet(QStringLiteral("delay"))) {
        faults.extraDelayMs = parser.value(QStringLiteral("delay")).toInt(&ok);
        if (!ok || faults.extraDelayMs < 0)
            return QStringLiteral("--delay needs a whole number of 0 or more.");
    }
    if (parser.isSet(QStringLiteral("seed"))) {
        faults.seed = parser.value(QStringLiteral("seed")).toUInt(&ok);
        if (!ok) return QStringLiteral("--seed needs a whole number.");
    }
    options.shared.throttle = !parser.isSet(QStringLiteral("no-throttle"));
    faults.dead = parser.isSet(QStringLiteral("dead"));
    options.verbose = parser.isSet(QStringLiteral("verbose"));
    return {};
}

void addOptions(QCommandLineParser& parser) {
    QStringList families;
    for (const FamilyInfo* family : FamilyRegistry::instance().all())
        families << (family->built ? family->id
                                   : QStringLiteral("%1 (not built yet)").arg(family->id));
    parser.setApplicationDescription(
        QStringLiteral("A simulated device of one family (see --family). Without --tcp it serves a "
                       "pseudo-terminal and prints its path as the first line on stdout."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addOptions({
        {QStringLiteral("family"),
         QStringLiteral("The device family: %1 (default: the protocol's family, else the first).")
             .arg(families.join(QStringLiteral(", "))),
         QStringLiteral("family")},
        {QStringLiteral("protocol"),
         QStringLiteral("A protocol of the family: %1 (default: the family's).")
             .arg(ProtocolRegistry::instance().idList()),
         QStringLiteral("protocol")},
        {QStringLiteral("tcp"),
         QStringLiteral("Serve TCP on this port instead of a pseudo-terminal."),
         QStringLiteral("port")},
        {QStringLiteral("corrupt"), QStringLiteral("Probability of a corrupted reply byte."),
         QStringLiteral("p")},
        {QStringLiteral("drop"),
         QStringLiteral("Probability of a lost reply (the request was executed)."),
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
        {QStringLiteral("dead"), QStringLiteral("Never answer.")},
        {QStringLiteral("verbose"), QStringLiteral("Log requests to stderr.")},
    });
    // Each family's own options (a name two families share is added once).
    QSet<QString> added;
    for (const SimulatorInfo* simulator : SimulatorRegistry::instance().all()) {
        for (const QCommandLineOption& option : simulator->options()) {
            if (added.contains(option.names().first())) continue;
            added.insert(option.names().first());
            parser.addOption(option);
        }
    }
}

}  // namespace

int main(int argc, char* argv[]) {
    cambench::registerBuiltins();
    if (!cambench::familiesComplete(cambench::Program::Simulator, "cambench-sim"))
        return 70;  // EX_SOFTWARE: this build lacks a family's part
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("cambench-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(CAMBENCH_VERSION_TEXT));
    QCommandLineParser parser;
    addOptions(parser);
    parser.process(app);
    Options options;
    if (QString problem = chooseSimulator(parser, options); !problem.isEmpty())
        return fail(problem);
    if (QString problem = readSharedOptions(parser, options); !problem.isEmpty())
        return fail(problem);
    Result<SimulatedLine> made = options.simulator->fromOptions(parser, options.shared);
    if (!made) return fail(made.error().message);
    SimulatedLine& line = made.value();
    QLoggingCategory::setFilterRules(
        options.verbose
            ? QStringLiteral("cambench.comm.sim.debug=true")
            : QStringLiteral("cambench.comm.sim.debug=false\ncambench.comm.sim.info=false"));

    SignalQuitter quitter;
    if (!quitter.isValid()) return fail(QStringLiteral("cannot watch for SIGTERM/SIGINT."));
    std::unique_ptr<QObject> server;
    if (options.tcpPort) {
        auto tcp = std::make_unique<SimTcpServer>(*line.endpoint, line.pacer);
        if (const Status listening = tcp->listen(*options.tcpPort); !listening)
            return fail(listening.error().message);
        std::printf("tcp://127.0.0.1:%u\n", unsigned(tcp->port()));
        server = std::move(tcp);
    } else {
        auto pty = std::make_unique<SimPtyServer>(*line.endpoint, line.pacer);
        if (const Status opened = pty->open(); !opened) return fail(opened.error().message);
        std::printf("%s\n", qPrintable(pty->slavePath()));
        server = std::move(pty);
    }
    std::fflush(stdout);
    const int code = app.exec();
    server.reset();  // before the line it serves
    return code;
}
