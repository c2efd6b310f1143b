#pragma once

namespace cambench::comm {

class FamilyRegistry;

// Announces the Parker Compax3 family ("compax3") in `registry`: known by name, not built
// into this CamBench yet, so that asking for it gets that answer.
void registerCompax3Family(FamilyRegistry& registry);

}  // namespace cambench::comm
