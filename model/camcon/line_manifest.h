#pragma once

// The manifest of a line backup (cambench-cli backup-line): which devices
// of a Multiuser line were backed up into which image, with the image's
// SHA-256 and the time, and which failed and why.
// {"format":"cambench-line-backup","version":1,"line":"...",
//  "devices":[{"device":5,"identity":{...},"file":"device-05_....json",
//              "sha256":"<hex of the file's bytes>","time":"<ISO UTC>",
//              "result":"saved"|"failed","message":"..."}]}

#include "device_info.h"
#include "model/result.h"

#include <QByteArray>
#include <QDateTime>
#include <QList>
#include <QString>

#include <optional>

namespace cambench {

constexpr int kLineManifestFormatVersion = 1;
// The manifest's file name inside the backup folder.
inline constexpr char kLineManifestName[] = "manifest.json";

struct LineManifestEntry {
    enum class Outcome { Saved, Failed };
    int device = 0;
    std::optional<DeviceInfo> identity;  // empty when the device did not answer
    QString file;    // image file name in the manifest's folder; empty when none
    QString sha256;  // lower-case hex of the image file's bytes
    QDateTime time;  // UTC, when the entry was made
    Outcome outcome = Outcome::Failed;
    QString message;  // why it failed, or a note ("kept from the run of ...")
};

struct LineManifest {
    QString line;                      // which line, for a person
    QList<LineManifestEntry> devices;  // in device-number order

    const LineManifestEntry* find(int device) const;
    // Replaces the entry of the same device or adds it in order.
    void put(const LineManifestEntry& entry);
    bool allSaved() const;
};

QByteArray lineManifestToJson(const LineManifest& manifest);
Result<LineManifest> lineManifestFromJson(const QByteArray& bytes);
Status saveLineManifest(const QString& path, const LineManifest& manifest);
Result<LineManifest> loadLineManifest(const QString& path);

// Lower-case hex SHA-256 of `bytes`.
QString sha256Hex(const QByteArray& bytes);

}  // namespace cambench
