#include "table_logging.h"

Q_LOGGING_CATEGORY(commTableLog, "cambench.comm.table", QtWarningMsg)
