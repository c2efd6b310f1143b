#pragma once

// The Compax3's backup part (issue 36): the drive's parameter set (every
// parameter of the dictionary the connection holds, each with its name)
// as a parameter file (model/compax3/compax3_parameter_file.h), on the use
// cases of compax3_parameters.h.

#include "comm/usecases/family_backup.h"

namespace cambench::usecases {

// It (the Compax3's FamilyParts::backup).
std::shared_ptr<const FamilyBackup> compax3Backup();

}  // namespace cambench::usecases
