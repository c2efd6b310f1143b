#include "protocol_log.h"

namespace cambench::comm {

Q_LOGGING_CATEGORY(commProtocolLog, "cambench.comm.protocol")

}  // namespace cambench::comm
