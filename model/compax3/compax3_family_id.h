#pragma once

#include <QString>

namespace cambench {

// The Compax3 family's id, spelled here and nowhere else: the CLI's
// --family value, the files' "family", and the key under which its
// FamilyParts (app/registry/compax3/) registers every part.
inline constexpr QLatin1String compax3FamilyId{"compax3"};

}  // namespace cambench
