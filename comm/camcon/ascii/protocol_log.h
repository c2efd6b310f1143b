#pragma once

#include <QLoggingCategory>

namespace cambench::comm {

Q_DECLARE_LOGGING_CATEGORY(commProtocolLog)

}  // namespace cambench::comm
