#include "eeprom_image_file.h"

#include "device_info_json.h"
#include "model/atomic_file.h"
#include "model/camcon/camcon_family_id.h"
#include "model/file_read.h"
#include "model/json_file.h"
#include "model/json_reader.h"
#include "model/readable_json.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>

#include <algorithm>
#include <cctype>

namespace cambench {

namespace {

const JsonFileType kImageFile{"cambench-eeprom-image", kEepromImageFormatVersion, "EEPROM image",
                              camconFamilyId.latin1()};
const QLatin1String kToolPrefix("CamBench ");
constexpr int kEndBlockNumber = 0xFFFF;

QString key(const char* text) {
    return QString::fromLatin1(text);
}

// Block numbers as the protocol writes them: 4 upper-case hex digits.
QString hex4(int number) {
    return QString::number(number, 16).toUpper().rightJustified(4, QLatin1Char('0'));
}

QString blockName(int index, int number) {
    return QCoreApplication::translate("cambench::model", "Block %1 (entry %2 of the list)")
        .arg(hex4(number))
        .arg(index);
}

QList<EepromBlock> readBlocks(JsonReader& reader, const QJsonArray& array) {
    QList<EepromBlock> blocks;
    for (int i = 0; i < array.size() && !reader.failed(); ++i) {
        const QString path = JsonReader::element(key("blocks"), i);
        const QJsonObject object = reader.objectValue(array.at(i), path);
        EepromBlock block;
        block.number =
            quint16(reader.integer(object, path, key("number"),
                                   QCoreApplication::translate("cambench::model", "block number"),
                                   0, kEndBlockNumber - 1));
        const QString hex =
            reader.string(object, path, key("data"),
                          QCoreApplication::translate("cambench::model", "block data"));
        const QByteArray latin = hex.toLatin1();
        const bool isHex =
            hex.size() % 2 == 0 && std::all_of(latin.cbegin(), latin.cend(),
                                               [](char c) { return std::isxdigit(uchar(c)) != 0; });
        if (!reader.failed() && !isHex) {
            reader.fail(JsonReader::member(path, key("data")),
                        QCoreApplication::translate(
                            "cambench::model", "block data is not an even number of hex digits"));
        }
        block.data = QByteArray::fromHex(latin);
        blocks << block;
    }
    return blocks;
}

}  // namespace

Status checkImageBlocks(const QList<EepromBlock>& blocks) {
    if (blocks.isEmpty())
        return Error::invalidData(
            QCoreApplication::translate("cambench::model", "The image holds no blocks."));
    const EepromBlock& first = blocks.first();
    if (first.number != 0) {
        return Error::invalidData(
            QCoreApplication::translate("cambench::model",
                                        "The image does not start with block 0000 (the "
                                        "basic parameters) but with block %1.")
                .arg(hex4(first.number)));
    }
    if (first.data.size() != kEepromBasicBlockBytes) {
        return Error::invalidData(
            QCoreApplication::translate("cambench::model",
                                        "Block 0000 has %1 bytes; the basic-parameter "
                                        "block has %2.")
                .arg(first.data.size())
                .arg(kEepromBasicBlockBytes));
    }
    for (int i = 1; i < blocks.size(); ++i) {
        const EepromBlock& block = blocks.at(i);
        const QString name = blockName(i, block.number);
        if (block.number <= blocks.at(i - 1).number) {
            return Error::invalidData(
                QCoreApplication::translate("cambench::model",
                                            "%1 does not follow block %2: block "
                                            "numbers must ascend.")
                    .arg(name)
                    .arg(hex4(blocks.at(i - 1).number)));
        }
        if (block.number >= kEndBlockNumber) {
            return Error::invalidData(
                QCoreApplication::translate("cambench::model",
                                            "%1: FFFF marks the end of the EEPROM and is no block.")
                    .arg(name));
        }
        if (block.data.isEmpty())
            return Error::invalidData(
                QCoreApplication::translate("cambench::model", "%1 is empty.").arg(name));
        const int nibble = uchar(block.data.at(0)) >> 4;
        if (nibble == 0) {
            return Error::invalidData(
                QCoreApplication::translate("cambench::model",
                                            "%1: its first byte 0x%2 gives no length "
                                            "(upper 4 bits are 0).")
                    .arg(name)
                    .arg(uchar(block.data.at(0)), 2, 16, QLatin1Char('0')));
        }
        if (block.data.size() != nibble * 6) {
            return Error::invalidData(
                QCoreApplication::translate("cambench::model",
                                            "%1 has %2 bytes, but its first byte 0x%3 "
                                            "says %4.")
                    .arg(name)
                    .arg(block.data.size())
                    .arg(uchar(block.data.at(0)), 2, 16, QLatin1Char('0'))
                    .arg(nibble * 6));
        }
    }
    return success();
}

QStringList identityMismatch(const DeviceInfo& image, const DeviceInfo& device) {
    const DeviceIdentity was = camConIdentity(image);
    const DeviceIdentity now = camConIdentity(device);
    QStringList differences;
    for (auto it = was.values().begin(); it != was.values().end(); ++it) {
        if (it.value() == now.value(it.key())) continue;
        differences << QCoreApplication::translate("cambench::model", "%1: image %2, device %3.")
                           .arg(it.key(), it.value(), now.value(it.key()));
    }
    return differences;
}

QByteArray eepromImageToJson(const EepromImage& image) {
    QJsonObject root = jsonFileHeader(kImageFile);
    root.insert(key("device"), deviceInfoToJson(image.device));
    root.insert(key("taken"), image.taken.toUTC().toString(Qt::ISODateWithMs));
    root.insert(key("tool"), kToolPrefix + image.toolVersion);
    QJsonArray blocks;
    for (const EepromBlock& block : image.blocks) {
        blocks.append(QJsonObject{{key("number"), block.number},
                                  {key("data"), QString::fromLatin1(block.data.toHex())}});
    }
    root.insert(key("blocks"), blocks);
    if (!image.content.isEmpty()) root.insert(key("content"), image.content);
    sealWithHash(root);
    return toReadableJson(root);
}

Result<EepromImage> eepromImageFromJson(const QByteArray& bytes) {
    const Result<QJsonObject> parsed = parseJsonFile(bytes, kImageFile);
    if (!parsed) return parsed.error();
    QJsonObject root = *parsed;
    if (const Status hash = takeCheckedHash(root); !hash) return hash.error();
    JsonReader reader;

    EepromImage image;
    image.device = readDeviceInfo(reader, reader.object(root, {}, key("device")), key("device"));
    const QString taken = reader.string(
        root, {}, key("taken"), QCoreApplication::translate("cambench::model", "time taken"));
    image.taken = QDateTime::fromString(taken, Qt::ISODateWithMs).toUTC();
    if (!reader.failed() && !image.taken.isValid()) {
        reader.fail(key("taken"), QCoreApplication::translate(
                                      "cambench::model", "\"%1\" is not an ISO 8601 date and time")
                                      .arg(taken));
    }
    const QString tool = reader.string(root, {}, key("tool"),
                                       QCoreApplication::translate("cambench::model", "tool"));
    image.toolVersion = tool.startsWith(kToolPrefix) ? tool.mid(kToolPrefix.size()) : tool;
    image.blocks = readBlocks(reader, reader.array(root, {}, key("blocks")));
    if (root.contains(key("content"))) image.content = reader.object(root, {}, key("content"));
    if (reader.failed()) return Error::invalidData(reader.problem() + QLatin1Char('.'));
    const Status blocks = checkImageBlocks(image.blocks);
    if (!blocks) return blocks.error();
    return image;
}

Status saveEepromImage(const QString& path, const EepromImage& image) {
    const Status blocks = checkImageBlocks(image.blocks);
    if (!blocks) {
        return Error::invalidData(
            QCoreApplication::translate("cambench::model", "%1 was not saved: %2")
                .arg(path, blocks.error().message));
    }
    // An image holds the users' access codes (notes 4 and 6).
    return writeFileAtomically(path, eepromImageToJson(image), FileAccess::OwnerOnly);
}

Result<EepromImage> loadEepromImage(const QString& path) {
    const Result<QByteArray> bytes = readFileBytes(path);
    if (!bytes) return bytes.error();
    Result<EepromImage> image = eepromImageFromJson(*bytes);
    if (!image) return inFile(path, image.error());
    return image;
}

}  // namespace cambench
