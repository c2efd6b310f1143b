#include "sim_options.h"

#include "comm/device/family_registry.h"
#include "comm/device/protocol_registry.h"

#include <QSet>

namespace cambench {

using namespace comm;

QString readSharedSimOptions(const QCommandLineParser& parser, SimCommandLine& options) {
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

void addSimOptions(QCommandLineParser& parser) {
    QStringList families;
    for (const FamilyInfo* family : FamilyRegistry::instance().all())
        families << (family->built ? family->id
                                   : QStringLiteral("%1 (not built yet)").arg(family->id));
    parser.setApplicationDescription(
        QStringLiteral("A simulated device of one family (see --family), or every device of a "
                       "machine (--machine). Without --tcp it serves a pseudo-terminal and "
                       "prints its path as the first line on stdout."));
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
         QStringLiteral("Serve TCP on this port instead of a pseudo-terminal (with --machine: the "
                        "first device's, the next on the next ports; 0: free ports)."),
         QStringLiteral("port")},
        {QStringLiteral("machine"),
         QStringLiteral("Every device of this machine file at once, each on its own "
                        "pseudo-terminal (or TCP port), printing \"NAME PATH\" a line; the file's "
                        "ports are left out, its shaft couples the devices."),
         QStringLiteral("file")},
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

}  // namespace cambench
