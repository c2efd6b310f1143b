#pragma once

namespace cambench::comm {

class FamilyRegistry;

// Registers the Parker Compax3 servo drives ("compax3") in `registry`; their
// protocols are registerCompax3Protocol (compax3_protocol.h).
void registerCompax3Family(FamilyRegistry& registry);

}  // namespace cambench::comm
