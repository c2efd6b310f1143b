#pragma once

namespace cambench::comm {

class FamilyRegistry;

// Adds the Digitronic CamCon family ("camcon") to `registry`.
void registerCamConFamily(FamilyRegistry& registry);

}  // namespace cambench::comm
