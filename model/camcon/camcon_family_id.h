#pragma once

#include <QString>

namespace cambench {

// The CamCon family's id, spelled here and nowhere else: the CLI's
// --family value, the files' "family", and the key under which its
// FamilyParts (app/registry/camcon/) registers every part.
inline constexpr QLatin1String camconFamilyId{"camcon"};

}  // namespace cambench
