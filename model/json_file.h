#pragma once

#include "result.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>

namespace cambench {

// The envelope every CamBench JSON file shares: {"format": ..., "version": n, ...}.
struct JsonFileType {
    const char* format;  // "cambench-project"
    int version;         // the version this build writes and reads
    const char* noun;    // "project", for messages
    // The device family the file is for ("camcon"), recorded in "family".
    // A file without it is from before families were recorded: the
    // CamCon's, the only family there was.
    const char* family = nullptr;
};

// The top-level object, once the bytes are JSON, the format matches and the
// version is one this build reads, and the family is the type's. A newer
// version gets its own message asking for a newer CamBench; a file of
// another device family says which.
Result<QJsonObject> parseJsonFile(const QByteArray& bytes, const JsonFileType& type);

// The envelope of a new file.
QJsonObject jsonFileHeader(const JsonFileType& type);

// Files that guard their content (backups, images) carry "sha256": the
// SHA-256 of the compact JSON of the same object without it. sealWithHash
// adds it; takeCheckedHash removes it and refuses a file whose content no
// longer matches (changed or damaged: not to be restored).
void sealWithHash(QJsonObject& root);
Status takeCheckedHash(QJsonObject& root);

// Indented JSON: QJsonObject keeps keys sorted, so equal data give
// byte-identical files that diff cleanly.
QByteArray toIndentedJson(const QJsonObject& object);

}  // namespace cambench
