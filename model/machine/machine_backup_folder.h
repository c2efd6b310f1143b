#pragma once

// A machine's backup folder (issue 30, issue 36 item 3): the machine file
// (machine.json, with each saved device's identity), one file per device
// (its family's backup) and manifest.json: who took it, why and with what
// (operator, note, tool version and git revision), when, and per device
// its name, family, file, identity, SHA-256, time and result. A restore's
// safety copies go to a folder beside it (never inside: the backup stays
// as it was taken), which is a backup folder of its own with a manifest
// that says of which folder it is the safety copy. Used alike by the
// machine commands and the machine window; names no family.

#include "model/device_identity.h"
#include "model/machine/machine_file.h"
#include "model/result.h"

#include <QByteArray>
#include <QDateTime>
#include <QList>
#include <QString>
#include <QStringList>

namespace cambench {

inline const QString kMachineBackupFile = QStringLiteral("machine.json");
inline const QString kMachineManifestFile = QStringLiteral("manifest.json");

// Who took a backup, why and with what.
struct BackupAuthor {
    QString operatorName;  // --operator; the login name when not given
    QString note;          // -m: why
    QString tool;          // CamBench's version ("0.9.0")
    QString revision;      // the git revision it was built from ("a7d0047", "+dirty")
};

// The login name of the person running the program ($USER, $LOGNAME,
// $USERNAME, else the user database's name of the user); "unknown" when
// none is known.
QString loginName();

// One device of the manifest.
struct ManifestEntry {
    QString name;
    QString family;
    QString file;  // in the folder: deviceFileName()
    // The identity of the device that answered; not known in a manifest
    // older than that record (it held identify()'s text there).
    DeviceIdentity identity;
    QString device;          // what it said of itself (identify())
    QString summary;         // what was saved ("1024 EEPROM blocks, 16 programs, ...")
    QStringList incomplete;  // items not saved, one sentence each
    QString sha256;          // of the file as saved
    QDateTime time;          // UTC, when it was saved
    QString result;          // "saved" or "failed: why"

    bool saved() const { return result == QLatin1String("saved"); }
};

struct MachineManifest {
    QString machine;
    BackupAuthor author;
    QDateTime started;  // UTC, when the backup began
    // The folder this one is the safety copy of (taken by a restore from
    // it before writing); empty for a backup a person took.
    QString safetyCopyOf;
    QList<ManifestEntry> devices;

    const ManifestEntry* entry(const QString& name) const;
};

// manifest.json's text: keys sorted, one device a line.
QByteArray manifestJson(const MachineManifest& manifest);
// `where` names it in messages. A manifest older than the author record
// reads with an empty author.
Result<MachineManifest> parseManifest(const QByteArray& bytes, const QString& where);

// The device's file in the folder: its name with anything but letters,
// digits, '.', '-' and '_' as '_' (a name may hold a slash), ".json".
QString deviceFileName(const QString& deviceName);

// The SHA-256 of the file at `path` in hex; empty when it cannot be read.
QString fileSha256(const QString& path);

// An entry that still holds in `dir`: saved, and its file unchanged since.
bool stillSaved(const ManifestEntry& entry, const QString& dir);

// The folder of a restore's safety copies: beside `dir`, named after it
// and the time ("press7-backup.safety-20261121T231500Z"; "-2", ... when
// that exists). Not made here.
QString safetyFolderPath(const QString& dir, const QDateTime& utc);

}  // namespace cambench
