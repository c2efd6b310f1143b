#include "protocol_log.h"

namespace cambench::comm {

// Debug messages (every skipped byte, every bad checksum) only when asked for
// with QT_LOGGING_RULES="cambench.comm.protocol.debug=true".
Q_LOGGING_CATEGORY(commProtocolLog, "cambench.comm.protocol", QtWarningMsg)

}  // namespace cambench::comm
