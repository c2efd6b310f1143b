#include "sim_log.h"

Q_LOGGING_CATEGORY(commSimLog, "cambench.comm.sim", QtWarningMsg)
