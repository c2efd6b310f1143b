#pragma once

#include "model/result.h"

#include <QString>

namespace cambench::comm {

// Prefixes a step to an error's message, keeping its kind and code:
// "reading program 3, output 5: <link message>".
inline Error inContext(const QString& step, const Error& error) {
    Error result = error;
    result.message = QStringLiteral("%1: %2").arg(step, error.message);
    return result;
}

}  // namespace cambench::comm
