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

void SimulatorRegistry::add(SimulatorInfo info) {
    for (auto& known : m_simulators) {
        if (known->familyId == info.familyId) {
            *known = std::move(info);  // registered twice (tests): the last one counts
            return;
        }
    }
    m_simulators.append(std::make_shared<SimulatorInfo>(std::move(info)));
}

const SimulatorInfo* SimulatorRegistry::find(const QString& familyId) const {
    for (const auto& simulator : m_simulators) {
        if (simulator->familyId == familyId) return simulator.get();
    }
    return nullptr;
}

const SimulatorInfo* SimulatorRegistry::forProtocol(const QString& protocol) const {
    if (const ProtocolInfo* info = ProtocolRegistry::instance().find(protocol)) {
        if (const SimulatorInfo* simulator = find(info->familyId)) return simulator;
    }
    return m_simulators.isEmpty() ? nullptr : m_simulators.first().get();
}

QList<const SimulatorInfo*> SimulatorRegistry::all() const {
    QList<const SimulatorInfo*> list;
    for (const auto& simulator : m_simulators) list.append(simulator.get());
    return list;
}

}  // namespace cambench::comm
