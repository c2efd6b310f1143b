#pragma once

// The fake family's backup part (issue 38, item 4): what the machine
// window's backup, verify, restore and versions need of a family, on a
// device small enough to see whole. A fake device holds numbered
// registers ("GET n" -> "VAL n v", "SET n v" -> "VAL n v") and an identity
// of its own (its serial number); the file is JSON of both.

#include "comm/usecases/family_backup.h"

#include <memory>

namespace cambench::fake {

std::shared_ptr<const usecases::FamilyBackup> fakeBackup();

}  // namespace cambench::fake
