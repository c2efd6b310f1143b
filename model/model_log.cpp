#include "model_log.h"

Q_LOGGING_CATEGORY(modelLog, "cambench.model", QtWarningMsg)
