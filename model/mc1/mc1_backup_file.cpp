#include "mc1_backup_file.h"

#include "model/atomic_file.h"
#include "model/file_read.h"
#include "model/json_file.h"
#include "model/json_reader.h"
#include "model/mc1/mc1_family_id.h"
#include "model/readable_json.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QRegularExpression>

namespace cambench {

namespace {

const JsonFileType kBackupFile{"cambench-mc1-backup", kMc1BackupFormatVersion, "MC-1 backup",
                               mc1FamilyId.latin1()};
const QLatin1String kToolPrefix("CamBench ");
constexpr int kPageBytes = 256;
constexpr int kMemoryEnd = 0x10000;

QString key(const char* text) {
    return QString::fromLatin1(text);
}

QByteArray fromHex(JsonReader& reader, const QString& hex, const QString& path) {
    static const QRegularExpression pattern(QStringLiteral("^([0-9a-fA-F]{2})*$"));
    if (!pattern.match(hex).hasMatch()) {
        reader.fail(path, QCoreApplication::translate("cambench::model",
                                                      "not an even number of hexadecimal digits"));
        return {};
    }
    return QByteArray::fromHex(hex.toLatin1());
}

void readVariables(JsonReader& reader, const QJsonArray& array, Mc1Backup& backup) {
    const int bits = backup.mc200() ? 32 : 24;
    const qint64 lowest = -(qint64(1) << (bits - 1));
    const qint64 highest = (qint64(1) << (bits - 1)) - 1;
    for (int i = 0; i < array.size() && !reader.failed(); ++i) {
        const QString path = JsonReader::element(key("variables"), i);
        const QJsonArray pair = reader.arrayValue(array.at(i), path);
        if (!reader.failed() && pair.size() != 2)
            reader.fail(
                path, QCoreApplication::translate("cambench::model", "not a pair [number, value]"));
        if (reader.failed()) return;
        const int number = int(reader.integerValue(
            pair.at(0), JsonReader::element(path, 0),
            QCoreApplication::translate("cambench::model", "variable number"), 0, 0xFFFF));
        const qint64 value = reader.integerValue(
            pair.at(1), JsonReader::element(path, 1),
            QCoreApplication::translate("cambench::model", "value (%1 bits)").arg(bits), lowest,
            highest);
        if (!reader.failed() && backup.variables.contains(number))
            reader.fail(
                path,
                QCoreApplication::translate("cambench::model", "V%1 a second time").arg(number));
        backup.variables.insert(number, value);
    }
}

// The flags one a line: each [name, 0 or 1] in bit order, the name the
// flag's at that bit (a line moved or edited by hand is refused).
QByteArray readFlags(JsonReader& reader, const QJsonArray& array, bool mc200) {
    if (array.isEmpty()) return {};
    if (array.size() != kPageBytes * 8) {
        reader.fail(key("flags"),
                    QCoreApplication::translate("cambench::model", "%1 flags, not the page's %2")
                        .arg(array.size())
                        .arg(kPageBytes * 8));
        return {};
    }
    QByteArray page(kPageBytes, '\0');
    for (int bit = 0; bit < array.size() && !reader.failed(); ++bit) {
        const QString path = JsonReader::element(key("flags"), bit);
        const QJsonArray pair = reader.arrayValue(array.at(bit), path);
        const QString name = QStringLiteral("M%1").arg(mc1ExternalFlagNumber(bit, mc200));
        if (!reader.failed() && (pair.size() != 2 || pair.at(0).toString() != name))
            reader.fail(
                path,
                QCoreApplication::translate("cambench::model", "not [\"%1\", 0 or 1]").arg(name));
        const qint64 on =
            reader.integerValue(pair.at(1), JsonReader::element(path, 1),
                                QCoreApplication::translate("cambench::model", "flag"), 0, 1);
        if (on) page[bit >> 3] = char(quint8(page.at(bit >> 3)) | (1u << (bit & 7)));
    }
    return page;
}

void readMemory(JsonReader& reader, const QJsonArray& array, Mc1Backup& backup) {
    int end = -1;
    for (int i = 0; i < array.size() && !reader.failed(); ++i) {
        const QString path = JsonReader::element(key("memory"), i);
        const QJsonObject object = reader.objectValue(array.at(i), path);
        Mc1MemoryRange range;
        range.address = int(reader.integer(
            object, path, key("address"), QCoreApplication::translate("cambench::model", "address"),
            0, kMemoryEnd - 1));
        range.data = fromHex(reader,
                             reader.string(object, path, key("data"),
                                           QCoreApplication::translate("cambench::model", "data")),
                             JsonReader::member(path, key("data")));
        if (reader.failed()) return;
        if (range.data.isEmpty() || range.address + range.data.size() > kMemoryEnd)
            reader.fail(path,
                        QCoreApplication::translate(
                            "cambench::model", "%1 bytes from 0x%2 do not fit memory 0x0000–0xFFFF")
                            .arg(range.data.size())
                            .arg(range.address, 4, 16, QLatin1Char('0')));
        else if (range.address < end)
            reader.fail(path,
                        QCoreApplication::translate(
                            "cambench::model", "overlaps the range before it or is out of order"));
        end = range.address + int(range.data.size());
        backup.memory << range;
    }
}

}  // namespace

int mc1ExternalFlagNumber(int index, bool mc200) {
    // MC100: M1–499 then M2000–3548 (tables 47 and 48).
    return mc200 || index < 499 ? index + 1 : index + 1501;
}

QByteArray mc1BackupToJson(const Mc1Backup& backup) {
    QJsonObject root = jsonFileHeader(kBackupFile);
    root.insert(key("variant"), backup.variant);
    if (backup.identity.known()) root.insert(key("identity"), backup.identity.toJson());
    root.insert(key("taken"), backup.taken.toUTC().toString(Qt::ISODateWithMs));
    root.insert(key("tool"), kToolPrefix + backup.toolVersion);
    QJsonArray variables;
    for (auto it = backup.variables.begin(); it != backup.variables.end(); ++it)
        variables.append(QJsonArray{it.key(), it.value()});
    root.insert(key("variables"), variables);
    root.insert(key("flagPage"), backup.flagPage);
    QJsonArray flags;
    for (int bit = 0; bit < backup.flags.size() * 8; ++bit)
        flags.append(
            QJsonArray{QStringLiteral("M%1").arg(mc1ExternalFlagNumber(bit, backup.mc200())),
                       (quint8(backup.flags.at(bit >> 3)) >> (bit & 7)) & 1});
    root.insert(key("flags"), flags);
    QJsonArray memory;
    for (const Mc1MemoryRange& range : backup.memory)
        memory.append(QJsonObject{{key("address"), range.address},
                                  {key("data"), QString::fromLatin1(range.data.toHex())}});
    root.insert(key("memory"), memory);
    sealWithHash(root);
    return toReadableJson(root);
}

Result<Mc1Backup> mc1BackupFromJson(const QByteArray& bytes) {
    const Result<QJsonObject> parsed = parseJsonFile(bytes, kBackupFile);
    if (!parsed) return parsed.error();
    QJsonObject root = *parsed;
    if (const Status hash = takeCheckedHash(root); !hash) return hash.error();
    JsonReader reader;
    Mc1Backup backup;
    backup.variant =
        reader.string(root, {}, key("variant"),
                      QCoreApplication::translate("cambench::model", "controller variant"));
    static const QRegularExpression variants(QStringLiteral("^mc(100|200)v[12]$"));
    if (!reader.failed() && !variants.match(backup.variant).hasMatch())
        reader.fail(key("variant"),
                    QCoreApplication::translate(
                        "cambench::model", "\"%1\" is none of mc100v1, mc100v2, mc200v1, mc200v2")
                        .arg(backup.variant));
    if (root.contains(key("identity"))) {
        const Result<DeviceIdentity> identity =
            DeviceIdentity::fromJson(root.value(key("identity")), key("identity"));
        if (!identity) return identity.error();
        backup.identity = *identity;
    }
    const QString taken = reader.string(
        root, {}, key("taken"), QCoreApplication::translate("cambench::model", "time taken"));
    backup.taken = QDateTime::fromString(taken, Qt::ISODateWithMs).toUTC();
    if (!reader.failed() && !backup.taken.isValid())
        reader.fail(key("taken"), QCoreApplication::translate(
                                      "cambench::model", "\"%1\" is not an ISO 8601 date and time")
                                      .arg(taken));
    const QString tool = reader.string(root, {}, key("tool"),
                                       QCoreApplication::translate("cambench::model", "tool"));
    backup.toolVersion = tool.startsWith(kToolPrefix) ? tool.mid(kToolPrefix.size()) : tool;
    readVariables(reader, reader.array(root, {}, key("variables")), backup);
    backup.flagPage =
        int(reader.integer(root, {}, key("flagPage"),
                           QCoreApplication::translate("cambench::model", "flag page"), 0, 255));
    backup.flags =
        root.value(key("flags")).isArray()
            ? readFlags(reader, root.value(key("flags")).toArray(), backup.mc200())
            : fromHex(reader,
                      reader.string(root, {}, key("flags"),
                                    QCoreApplication::translate("cambench::model", "flags")),
                      key("flags"));
    if (!reader.failed() && !backup.flags.isEmpty() && backup.flags.size() != kPageBytes)
        reader.fail(key("flags"),
                    QCoreApplication::translate("cambench::model", "%1 bytes, not the page's %2")
                        .arg(backup.flags.size())
                        .arg(kPageBytes));
    readMemory(reader, reader.array(root, {}, key("memory")), backup);
    if (reader.failed()) return Error::invalidData(reader.problem() + QLatin1Char('.'));
    return backup;
}

Status saveMc1Backup(const QString& path, const Mc1Backup& backup) {
    return writeFileAtomically(path, mc1BackupToJson(backup), FileAccess::Default);
}

Result<Mc1Backup> loadMc1Backup(const QString& path) {
    const Result<QByteArray> bytes = readFileBytes(path);
    if (!bytes) return bytes.error();
    Result<Mc1Backup> backup = mc1BackupFromJson(*bytes);
    if (!backup) return inFile(path, backup.error());
    return backup;
}

}  // namespace cambench
