#include "transport_logging.h"

Q_LOGGING_CATEGORY(commSerialLog, "cambench.comm.serial", QtWarningMsg)
