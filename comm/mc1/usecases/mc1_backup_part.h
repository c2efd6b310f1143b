#pragma once

// The MC-1's backup part (issue 36): its variables, external flags (and
// memory ranges) as a backup file (model/mc1/mc1_backup_file.h), on the
// use cases of mc1_backup_restore.h.

#include "comm/usecases/family_backup.h"

namespace cambench::usecases {

// It (the MC-1's FamilyParts::backup).
std::shared_ptr<const FamilyBackup> mc1Backup();

}  // namespace cambench::usecases
