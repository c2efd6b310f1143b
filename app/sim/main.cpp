// cambench-sim: a simulated device of any registered family on a
// pseudo-terminal (default) or a TCP port, or every device of a machine
// file at once (--machine), for the tool, its tests and demos without
// hardware. The options every family shares (protocol, faults, pacing,
// where to serve) are read here; the family's simulator reads its own.

#include "app/registry/builtin_registry.h"
#include "app/registry/family_parts.h"
#include "cambench_version.h"
#include "signal_quitter.h"
#include "sim_machine.h"
#include "sim_options.h"

#include "comm/device/family_registry.h"
#include "comm/device/protocol_registry.h"
#include "comm/sim/sim_pty_server.h"
#include "comm/sim/sim_tcp_server.h"
#include "comm/sim/simulator_registry.h"

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

int fail(const QString& message) {
    QTextStream(stderr) << "cambench-sim: " << message << Qt::endl;
    return 2;
}

// The family's simulator: --family, else the family of --protocol, else the
// default family (the first registered).
QString chooseSimulator(const QCommandLineParser& parser, SimCommandLine& options,
                        const SimulatorInfo** simulator) {
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
    *simulator = SimulatorRegistry::instance().find(familyId);
    if (!*simulator)
        return QStringLiteral("no simulator of family %1 is built into this CamBench.")
            .arg(familyId);
    options.shared.protocol = protocol;
    return {};
}

// --machine takes each device's family and options from the file: the same
// on the command line would be ignored, so it is refused.
QString deviceOptionOnCommandLine(const QCommandLineParser& parser) {
    QStringList names{QStringLiteral("family"), QStringLiteral("protocol")};
    for (const SimulatorInfo* simulator : SimulatorRegistry::instance().all())
        for (const QCommandLineOption& option : simulator->options()) names << option.names();
    for (const QString& name : names)
        if (parser.isSet(name))
            return QStringLiteral(
                       "--%1 is a device's option: with --machine give it in the "
                       "device's entry of the machine file.")
                .arg(name);
    return {};
}

void quietUnless(bool verbose) {
    QLoggingCategory::setFilterRules(
        verbose ? QStringLiteral("cambench.comm.sim.debug=true\ncambench.comm.sim.info=true")
                : QStringLiteral("cambench.comm.sim.debug=false\ncambench.comm.sim.info=false"));
}

// --machine FILE: every device, one "NAME PATH" line each, until a signal.
int serveMachine(QCoreApplication& app, const QCommandLineParser& parser,
                 const SimCommandLine& options) {
    if (QString problem = deviceOptionOnCommandLine(parser); !problem.isEmpty())
        return fail(problem);
    Result<std::unique_ptr<SimMachine>> machine =
        SimMachine::build(parser.value(QStringLiteral("machine")), options.shared);
    if (!machine) return fail(machine.error().message);
    quietUnless(options.verbose);
    SignalQuitter quitter;
    if (!quitter.isValid()) return fail(QStringLiteral("cannot watch for SIGTERM/SIGINT."));
    const Result<QStringList> served = (*machine)->serve(options.tcpPort);
    if (!served) return fail(served.error().message);
    for (const QString& line : *served) std::printf("%s\n", qPrintable(line));
    std::fflush(stdout);
    return app.exec();
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
    addSimOptions(parser);
    parser.process(app);
    SimCommandLine options;
    if (QString problem = readSharedSimOptions(parser, options); !problem.isEmpty())
        return fail(problem);
    if (parser.isSet(QStringLiteral("machine"))) return serveMachine(app, parser, options);
    const SimulatorInfo* simulator = nullptr;
    if (QString problem = chooseSimulator(parser, options, &simulator); !problem.isEmpty())
        return fail(problem);
    Result<SimulatedLine> made = simulator->fromOptions(parser, options.shared);
    if (!made) return fail(made.error().message);
    SimulatedLine& line = made.value();
    quietUnless(options.verbose);

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
