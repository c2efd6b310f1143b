#pragma once

#include "model/result.h"

#include <QByteArray>
#include <QJsonDocument>
#include <QString>
#include <QStringList>

namespace cambench::cli {

// "cambench-cli: <message>" on stderr.
void printError(const QString& message);
// Prints the error (usage errors: and the usage) and returns its exit code.
int reportError(const Error& error);

void printOut(const QString& text);  // stdout, as UTF-8
// Prints `document` indented on stdout; returns ExitOk.
int printJson(const QJsonDocument& document);

// Writes `data` to `path` atomically, or to stdout when `path` is empty or "-".
Status writeOutput(const QString& path, const QByteArray& data);

}  // namespace cambench::cli
