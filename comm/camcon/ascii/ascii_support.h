#pragma once

#include "fields.h"

#include "comm/device/error_context.h"
#include "model/result.h"

#include <QString>

#include <limits>

// Small helpers shared by the CamConClient .cpp files (not part of its API).
namespace cambench::comm::client {

// The only place where the 1-based output numbers of the model meet the
// 0-based numbers of the ASCII protocol.
inline qint64 wireOutput(int output) {
    return output - 1;
}

// Device texts are single-byte characters padded with NUL.
inline QString text(const Fields& fields, const char* name) {
    return QString::fromLatin1(fields.bytes(name));
}
inline QByteArray wireText(const QString& text) {
    return text.toLatin1();
}

// Both points of an empty track or of a search past the end (notes 3).
inline bool isNoCamPoint(qint64 point) {
    return point == std::numeric_limits<qint32>::min() || point == 0x80000000LL;
}

inline bool isNotUnderstood(const Error& error) {
    return error.kind == ErrorKind::NotUnderstood;
}

using comm::inContext;

}  // namespace cambench::comm::client
