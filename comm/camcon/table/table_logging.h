#pragma once

#include <QLoggingCategory>

// The table interface's link and device: 3964R handshakes, telegrams.
Q_DECLARE_LOGGING_CATEGORY(commTableLog)
