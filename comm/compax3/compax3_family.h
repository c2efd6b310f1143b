#pragma once

namespace cambench::comm {

struct FamilyInfo;

// The family of the Parker Compax3 servo drives: its title, default
// protocol and that it is built (its id is its FamilyParts', the constant
// of model/compax3/compax3_family_id.h); its protocols are compax3Protocols (compax3_protocol.h).
FamilyInfo compax3Family();

}  // namespace cambench::comm
