#pragma once

#include "sim_endpoint.h"
#include "sim_faults.h"
#include "sim_pacer.h"
#include "sim_shaft.h"

#include "comm/device/id_registry.h"
#include "comm/transport/transport.h"
#include "model/result.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QList>
#include <QString>

#include <functional>
#include <memory>
#include <optional>

namespace cambench::comm {

// A simulated line ready to serve: the device side, the pace its replies
// keep, and a description for messages.
struct SimulatedLine {
    std::unique_ptr<SimEndpoint> endpoint;
    SimPacer pacer;
    QString description;
    // Whether and how its device drives or follows a shaft (sim_shaft.h).
    SimShaftPlug shaft{};
};

// What cambench-sim reads for every family: the protocol asked for (empty:
// the family's default) and the faults every simulator can inject.
struct SimHostOptions {
    QString protocol;
    SimFaultSettings faults;  // corrupt, drop, ignore, drop-first, delay, seed, dead
    bool throttle = true;
};

// The simulator of one device family, registered from app/ beside the
// family (one line); the host - the in-process "sim" port, cambench-sim's
// pseudo-terminal and TCP servers, pacing, shared faults - names no family.
struct SimulatorInfo {
    QString familyId;
    // "sim" or "sim:key=value;..." as the PC connects with `protocol` (an
    // id of this family's protocols, or empty for its default).
    std::function<Result<SimulatedLine>(const QString& port, const SerialSettings& serial,
                                        const QString& protocol)>
        fromPort;
    // cambench-sim: the options only this family has, and the line they
    // and the shared options describe (a Usage error names the option).
    std::function<QList<QCommandLineOption>()> options;
    std::function<Result<SimulatedLine>(const QCommandLineParser& parser,
                                        const SimHostOptions& shared)>
        fromOptions;
    // The protocol "sim:key=value;..." names by its own keys, whatever the
    // PC speaks (empty: none; the device then speaks the PC's). Optional.
    std::function<QString(const QString& port)> namedProtocol = nullptr;
};

// "0.25" -> 0.25; nullopt unless a number 0..1 (the fault options).
std::optional<double> parseProbability(const QString& text);

// "sim" or "sim:key=value;...": a port of the in-process simulator.
bool isSimPort(const QString& port);

class SimulatorRegistry : public IdRegistry<SimulatorInfo, &SimulatorInfo::familyId> {
public:
    static SimulatorRegistry& instance();

    // The simulator of the family `protocol` belongs to; the first one
    // registered when the protocol is empty or unknown.
    const SimulatorInfo* forProtocol(const QString& protocol) const;
};

}  // namespace cambench::comm
