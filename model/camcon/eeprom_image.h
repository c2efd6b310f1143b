#pragma once

#include "device_info.h"

#include <QByteArray>
#include <QDateTime>
#include <QJsonObject>
#include <QList>

namespace cambench {

// One EEPROM block exactly as the device sent it (the blocks are opaque).
struct EepromBlock {
    quint16 number = 0;
    QByteArray data;  // unescaped binary data
    friend bool operator==(const EepromBlock& a, const EepromBlock& b) {
        return a.number == b.number && a.data == b.data;
    }
};

// A whole-EEPROM backup: the identity of the device it came from and the
// blocks read by ?EE 0000, 0001, ... until FFFF.
struct EepromImage {
    DeviceInfo device;
    QDateTime taken;      // UTC
    QString toolVersion;  // CamBench version that took it
    QList<EepromBlock> blocks;
    // The same content decoded for a person (issue 36): the device's
    // project as read alongside the blocks (programs, cams, dead times,
    // names, settings, users without their numbers, PLC networks), a
    // project file's object without its read times. Empty in an image of
    // an older format or a safety backup. Never restored: a restore writes
    // the blocks.
    QJsonObject content;

    int totalBytes() const;
};

}  // namespace cambench
