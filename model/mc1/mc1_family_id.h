#pragma once

#include <QString>

namespace cambench {

// The MC-1 (MC100/MC200) family's id, spelled here and nowhere else: the CLI's
// --family value, the files' "family", and the key under which its
// FamilyParts (app/registry/mc1/) registers every part.
inline constexpr QLatin1String mc1FamilyId{"mc1"};

}  // namespace cambench
