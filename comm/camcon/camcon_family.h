#pragma once

namespace cambench::comm {

struct FamilyInfo;

// The family of the Digitronic CamCon cam controllers: its title, default
// protocol and that it is built (its id is its FamilyParts', the constant
// of model/camcon/camcon_family_id.h); its protocols are camconProtocols (app/registry/camcon).
FamilyInfo camconFamily();

}  // namespace cambench::comm
