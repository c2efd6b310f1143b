#include "simulator_registry.h"

#include "comm/device/protocol_registry.h"

namespace cambench::comm {

std::optional<double> parseProbability(const QString& text) {
    bool ok = false;
    const double p = text.toDouble(&ok);
    if (!ok || p < 0.0 || p > 1.0) return std::nullopt;
    return p;
}

SimulatorRegistry& SimulatorRegistry::instance() {
    static SimulatorRegistry registry;
    return registry;
}

const SimulatorInfo* SimulatorRegistry::forProtocol(const QString& protocol) const {
    if (const ProtocolInfo* info = ProtocolRegistry::instance().find(protocol)) {
        if (const SimulatorInfo* simulator = find(info->familyId)) return simulator;
    }
    return all().value(0);
}

}  // namespace cambench::comm
