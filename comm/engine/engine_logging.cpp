#include "engine_logging.h"

Q_LOGGING_CATEGORY(commLinkLog, "cambench.comm.link", QtWarningMsg)
