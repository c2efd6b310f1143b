#pragma once

// What a verify or a diff found, whatever the family (issue 36): the
// differences in the family's own terms, one a line, and the exit code
// every verify shares (0 equal, 1 differs).

#include "cli_session.h"

#include "comm/usecases/family_backup.h"

#include <QString>

namespace cambench::cli {

// The notes, the differences one a line, then "equal: N items compared"
// or "D differences in N items compared". Returns ExitOk or ExitDevice.
int printComparison(const usecases::BackupComparison& comparison);

// `verify FILE` of the device on `session` through the backup part of
// the family `familyId` (the file is checked before the line is opened).
int verifyWithPart(CliSession& session, const QString& familyId, const QString& path);

}  // namespace cambench::cli
