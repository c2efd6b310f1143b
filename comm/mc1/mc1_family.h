#pragma once

namespace cambench::comm {

struct FamilyInfo;

// The family of the MICRO DESIGN MC100/MC200 (MC-1) motion controllers: its title, default
// protocol and that it is built (its id is its FamilyParts', the constant
// of model/mc1/mc1_family_id.h); its protocols are mc1Protocols (mc1_protocol.h).
FamilyInfo mc1Family();

}  // namespace cambench::comm
