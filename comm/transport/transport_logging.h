#pragma once

#include <QLoggingCategory>

// Serial and TCP transports share one category: a serial device server is a
// serial line reached over the network.
Q_DECLARE_LOGGING_CATEGORY(commSerialLog)
