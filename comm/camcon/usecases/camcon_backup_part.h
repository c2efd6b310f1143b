#pragma once

// The CamCon's backup part (issue 36): the whole EEPROM image and the same
// content decoded (model/camcon/eeprom_image_file.h,
// model/camcon/project_content.h), on the use cases of backup_restore.h.
// Differences are named in the content's terms ("program 0, output 5: cam
// 100–200 added"); where the content is equal but the blocks are not, or
// the backup is of the older format without content, the blocks are named.

#include "comm/usecases/family_backup.h"

namespace cambench::usecases {

// It (the CamCon's FamilyParts::backup).
std::shared_ptr<const FamilyBackup> camconBackup();

}  // namespace cambench::usecases
