// The one place of the shell that names the built-in families: one line
// each, in the order Detect tries them and --family defaults (the CamCon
// first). Everything else of a family is named in its parts file.
#include "builtin_registry.h"

#include "app/registry/camcon/camcon_parts.h"
#include "app/registry/compax3/compax3_parts.h"
#include "app/registry/mc1/mc1_parts.h"
#include "comm/sim/sim_transport.h"
#include "comm/transport/transport_registry.h"

namespace cambench {

void registerBuiltins() {
    comm::TransportRegistry& transports = comm::TransportRegistry::instance();
    comm::registerSimTransport(transports);
    comm::registerLineTransports(transports);  // serial is the catch-all: last

    for (const FamilyParts& parts : {camconParts(), mc1Parts(), compax3Parts()})
        registerFamily(parts);
}

}  // namespace cambench
