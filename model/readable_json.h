#pragma once

// JSON a person reads and git diffs line by line (issue 36, item 2): one
// item a line. The top-level object and every object that holds objects
// are indented, a key a line; an array that holds anything but plain
// values is one element a line, and an element without objects inside
// (a variable [12, 4711], an object [\"1902.1\", \"200\", \"Set 1
// velocity\"], a cam track {"cams": [[100, 200]], "output": 5}) stays on
// its line. Keys come sorted (QJsonObject), so equal data give equal
// bytes. Reads back with any JSON parser; the compact form (and so the
// files' SHA-256) is the same as of QJsonDocument.

#include <QByteArray>
#include <QJsonObject>

namespace cambench {

QByteArray toReadableJson(const QJsonObject& object);

}  // namespace cambench
