#pragma once

namespace cambench::comm {

class FamilyRegistry;

// Registers the MICRO DESIGN MC100/MC200 (MC-1) family ("mc1") in `registry`;
// its protocol is registerMc1Protocol (mc1_protocol.h).
void registerMc1Family(FamilyRegistry& registry);

}  // namespace cambench::comm
