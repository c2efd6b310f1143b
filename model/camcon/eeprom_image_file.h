#pragma once

#include "device_info.h"
#include "eeprom_image.h"
#include "model/result.h"

#include <QByteArray>
#include <QList>
#include <QString>
#include <QStringList>

namespace cambench {

// 2: the content decoded beside the blocks, one item a line; version 1
// images (the blocks alone) still load and restore byte for byte.
constexpr int kEepromImageFormatVersion = 2;
// Block 0000 is the basic-parameter block (notes 6).
constexpr int kEepromBasicBlockBytes = 128;

// Whether the blocks can be restored as they are: block 0 first and 128
// bytes long, numbers strictly ascending below FFFF (the end marker), and
// every later block as long as its first byte says ((byte >> 4) * 6, with
// a nibble of 0 invalid). The message names the offending block.
Status checkImageBlocks(const QList<EepromBlock>& blocks);

// Differences between the identity (camConIdentity) of the device an image
// was taken from and of the device it is about to be restored to, one
// sentence each ("outputs: image 48, device 32."); empty when they match. A
// restore over a difference needs the person's word that this device
// replaces that one.
QStringList identityMismatch(const DeviceInfo& image, const DeviceInfo& device);

// {"format":"cambench-eeprom-image","version":2,"device":{...},"taken":ISO UTC,
//  "tool":"CamBench x.y.z","blocks":[{"number":0,"data":"<hex>"},...],
//  "content":{...a project...},"sha256":"<hex>"}, where sha256 is taken over
// the compact JSON of the same object without "sha256" (so the content
// cannot be edited unnoticed either). One item a line (toReadableJson): a
// block, a cam track, a dead time, a setting.
QByteArray eepromImageToJson(const EepromImage& image);
// Checks format, version, the hash (a mismatch means the file was changed
// or damaged), the device, and the blocks (checkImageBlocks).
Result<EepromImage> eepromImageFromJson(const QByteArray& bytes);

// Refuses blocks that checkImageBlocks rejects; writes atomically.
Status saveEepromImage(const QString& path, const EepromImage& image);
Result<EepromImage> loadEepromImage(const QString& path);

}  // namespace cambench
