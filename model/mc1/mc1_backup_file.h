#pragma once

#include "model/device_identity.h"
#include "model/result.h"

#include <QByteArray>
#include <QDateTime>
#include <QList>
#include <QMap>
#include <QString>

namespace cambench {

// 2: the flags one a line (["M12", 1]); version 1 files (the page as
// one hex string) still load.
constexpr int kMc1BackupFormatVersion = 2;

// The number of the flag at bit `index` of the external flag page (bit 0
// of byte 0 first): M1–M2048 on an MC200; M1–M499, then M2000–M3548 on an
// MC100 (tables 47 and 48).
int mc1ExternalFlagNumber(int index, bool mc200);

// A range of an MC200's memory as it was read.
struct Mc1MemoryRange {
    int address = 0;
    QByteArray data;
};

// What `mc backup` saves of an MC100/MC200: variables, the external flag
// page, memory ranges.
struct Mc1Backup {
    QString variant;  // "mc200v2" (comm/mc1/mc1_variant.h keys)
    // The controller it was taken from (Mc1Device::readIdentity); not known
    // in a backup older than that record.
    DeviceIdentity identity;
    QDateTime taken;
    QString toolVersion;
    QMap<int, qint64> variables;  // number -> value
    int flagPage = 0;             // the external RAM page of the flags
    QByteArray flags;             // that page: 256 bytes, or empty when not saved
    QList<Mc1MemoryRange> memory;

    // Whether the variant is an MC200 (32-bit variables) or an MC100 (24).
    bool mc200() const { return variant.startsWith(QLatin1String("mc200")); }
};

// {"format":"cambench-mc1-backup","version":2,"family":"mc1",
//  "variant":"mc200v2","identity":{"variant":"mc200v2","axes":…,…},
//  "taken":ISO UTC,"tool":"CamBench x.y.z",
//  "variables":[[1,-250],[2,-150],...],"flagPage":0,
//  "flags":[["M1",0],["M2",1],...] (every flag of the page, in bit order),
//  "memory":[{"address":4096,"data":"<hex>"}],"sha256":"<hex>"}, sha256
// over the compact JSON of the same object without "sha256". One item a
// line (toReadableJson): two backups diff line by line.
QByteArray mc1BackupToJson(const Mc1Backup& backup);
// Checks format, version, family, the hash (a mismatch: changed or
// damaged), the variant, the identity (optional: older backups lack it), every value against its
// width, the page size and the memory ranges (inside 0x0000–0xFFFF, not overlapping).
Result<Mc1Backup> mc1BackupFromJson(const QByteArray& bytes);

Status saveMc1Backup(const QString& path, const Mc1Backup& backup);
Result<Mc1Backup> loadMc1Backup(const QString& path);

}  // namespace cambench
