#pragma once

#include <QLoggingCategory>

namespace cambench {

// The desktop shell's category ("cambench.ui", see docs/architecture.md).
Q_DECLARE_LOGGING_CATEGORY(shellLog)

}  // namespace cambench
