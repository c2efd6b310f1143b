#pragma once

namespace cambench::comm {

class FamilyRegistry;

// Announces the MICRO DESIGN MC100/MC200 (MC-1) family ("mc1") in `registry`: known by name, not
// built into this CamBench yet, so that asking for it gets that answer.
void registerMc1Family(FamilyRegistry& registry);

}  // namespace cambench::comm
