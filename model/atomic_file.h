#pragma once

#include "result.h"

#include <QByteArray>
#include <QString>

namespace cambench {

// Replaces `path` with `bytes` or leaves it untouched (QSaveFile): a crash or
// a full disk never leaves half a file behind. The error says which file,
// why, and that nothing was changed.
Status writeFileAtomically(const QString& path, const QByteArray& bytes);

}  // namespace cambench
