#include "worker_logging.h"

Q_LOGGING_CATEGORY(commWorkerLog, "cambench.comm.worker", QtWarningMsg)
