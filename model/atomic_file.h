#pragma once

#include "result.h"

#include <QByteArray>
#include <QString>

namespace cambench {

// Who may read a written file: as the user's umask says, or its owner only
// (a file that holds secrets, such as an EEPROM image with access codes).
enum class FileAccess { Default, OwnerOnly };

// Replaces `path` with `bytes` or leaves it untouched (QSaveFile): a crash or
// a full disk never leaves half a file behind. The error says which file,
// why, and that nothing was changed. With OwnerOnly the file is 0600 before
// the first byte is written.
Status writeFileAtomically(const QString& path, const QByteArray& bytes,
                           FileAccess access = FileAccess::Default);

}  // namespace cambench
