#pragma once

#include "result.h"

#include <QByteArray>
#include <QString>

namespace cambench {

// Every file CamBench reads (projects, images, CSV) is small; the cap keeps
// a wrong path such as /dev/zero or a huge foreign file from hanging the tool.
constexpr qint64 kMaxReadFileBytes = 64 * 1024 * 1024;

// The whole content of a regular file of at most `maxBytes` bytes.
Result<QByteArray> readFileBytes(const QString& path, qint64 maxBytes = kMaxReadFileBytes);

// The same error with "<path>: " in front, for messages about a file's content.
Error inFile(const QString& path, const Error& error);

// Reads `path` and parses its bytes with `parse`; a parse error names the file.
template <class T>
Result<T> loadFileWith(const QString& path, Result<T> (*parse)(const QByteArray&)) {
    const Result<QByteArray> bytes = readFileBytes(path);
    if (!bytes) return bytes.error();
    Result<T> value = parse(*bytes);
    if (!value) return inFile(path, value.error());
    return value;
}

}  // namespace cambench
