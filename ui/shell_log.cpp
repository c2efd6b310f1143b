#include "shell_log.h"

namespace cambench {

Q_LOGGING_CATEGORY(shellLog, "cambench.ui", QtWarningMsg)

}  // namespace cambench
