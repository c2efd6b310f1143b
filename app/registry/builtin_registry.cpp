#include "builtin_registry.h"

#include "comm/camcon/ascii/ascii_protocol.h"
#include "comm/camcon/cambus/cambus_protocol.h"
#include "comm/camcon/camcon_family.h"
#include "comm/camcon/table/table_protocol.h"
#include "comm/camcon/usecases/camcon_check.h"
#include "comm/compax3/compax3_family.h"
#include "comm/compax3/compax3_protocol.h"
#include "comm/compax3/usecases/compax3_check.h"
#include "comm/device/family_registry.h"
#include "comm/device/protocol_registry.h"
#include "comm/mc1/mc1_family.h"
#include "comm/mc1/mc1_protocol.h"
#include "comm/mc1/usecases/mc1_check.h"
#include "comm/sim/camcon/camcon_simulator.h"
#include "comm/sim/compax3/compax3_simulator.h"
#include "comm/sim/mc1/mc1_simulator.h"
#include "comm/sim/sim_transport.h"
#include "comm/transport/transport_registry.h"

namespace cambench {

void registerBuiltins() {
    comm::TransportRegistry& transports = comm::TransportRegistry::instance();
    comm::registerSimTransport(transports);
    comm::registerLineTransports(transports);  // serial is the catch-all: last

    comm::FamilyRegistry& families = comm::FamilyRegistry::instance();
    comm::registerCamConFamily(families);
    comm::registerMc1Family(families);
    comm::registerCompax3Family(families);

    comm::ProtocolRegistry& protocols = comm::ProtocolRegistry::instance();
    comm::registerCamConAscii(protocols);
    comm::registerCamConTable(protocols);
    comm::registerCamConCamBus(protocols);
    comm::registerMc1Protocol(protocols);
    comm::registerCompax3Protocol(protocols);

    comm::SimulatorRegistry& simulators = comm::SimulatorRegistry::instance();
    comm::registerCamConSimulator(simulators);
    comm::registerMc1Simulator(simulators);
    comm::registerCompax3Simulator(simulators);

    usecases::CheckRegistry& checks = usecases::CheckRegistry::instance();
    usecases::registerCamConCheck(checks);
    usecases::registerMc1Check(checks);
    usecases::registerCompax3Check(checks);
}

}  // namespace cambench
