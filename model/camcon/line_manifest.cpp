#include "line_manifest.h"

#include "device_info_json.h"
#include "model/atomic_file.h"
#include "model/camcon/camcon_family_id.h"
#include "model/file_read.h"
#include "model/json_file.h"
#include "model/json_reader.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QJsonArray>

#include <algorithm>

namespace cambench {

namespace {

const JsonFileType kManifestFile{"cambench-line-backup", kLineManifestFormatVersion,
                                 "line backup manifest", camconFamilyId.latin1()};

QString key(const char* text) {
    return QString::fromLatin1(text);
}

QString outcomeText(LineManifestEntry::Outcome outcome) {
    return outcome == LineManifestEntry::Outcome::Saved ? key("saved") : key("failed");
}

QJsonObject entryToJson(const LineManifestEntry& entry) {
    QJsonObject object{{key("device"), entry.device},
                       {key("file"), entry.file},
                       {key("sha256"), entry.sha256},
                       {key("time"), entry.time.toUTC().toString(Qt::ISODate)},
                       {key("result"), outcomeText(entry.outcome)},
                       {key("message"), entry.message}};
    if (entry.identity) object.insert(key("identity"), deviceInfoToJson(*entry.identity));
    return object;
}

LineManifestEntry entryFromJson(JsonReader& reader, const QJsonValue& value, const QString& path) {
    const QJsonObject object = reader.objectValue(value, path);
    LineManifestEntry entry;
    if (reader.failed()) return entry;
    entry.device = int(reader.integer(object, path, key("device"), key("device"), 0, 63));
    entry.file = reader.string(object, path, key("file"), key("file"));
    entry.sha256 = reader.string(object, path, key("sha256"), key("sha256"));
    const QString time = reader.string(object, path, key("time"), key("time"));
    entry.time = QDateTime::fromString(time, Qt::ISODate);
    if (!reader.failed() && !entry.time.isValid())
        reader.fail(
            JsonReader::member(path, key("time")),
            QCoreApplication::translate("cambench::model", "\"%1\" is no ISO time").arg(time));
    const QString result = reader.string(object, path, key("result"), key("result"));
    if (!reader.failed() && result != key("saved") && result != key("failed"))
        reader.fail(JsonReader::member(path, key("result")),
                    QCoreApplication::translate("cambench::model",
                                                "\"%1\" is neither \"saved\" nor \"failed\"")
                        .arg(result));
    entry.outcome = result == key("saved") ? LineManifestEntry::Outcome::Saved
                                           : LineManifestEntry::Outcome::Failed;
    entry.message = reader.string(object, path, key("message"), key("message"));
    if (object.contains(key("identity"))) {
        const QString identityPath = JsonReader::member(path, key("identity"));
        entry.identity =
            readDeviceInfo(reader, reader.object(object, path, key("identity")), identityPath);
    }
    return entry;
}

}  // namespace

const LineManifestEntry* LineManifest::find(int device) const {
    for (const LineManifestEntry& entry : devices) {
        if (entry.device == device) return &entry;
    }
    return nullptr;
}

void LineManifest::put(const LineManifestEntry& entry) {
    for (LineManifestEntry& existing : devices) {
        if (existing.device == entry.device) {
            existing = entry;
            return;
        }
    }
    const auto at = std::find_if(devices.begin(), devices.end(), [&](const LineManifestEntry& e) {
        return e.device > entry.device;
    });
    devices.insert(at, entry);
}

bool LineManifest::allSaved() const {
    return !devices.isEmpty() &&
           std::all_of(devices.cbegin(), devices.cend(), [](const LineManifestEntry& e) {
               return e.outcome == LineManifestEntry::Outcome::Saved;
           });
}

QByteArray lineManifestToJson(const LineManifest& manifest) {
    QJsonObject root = jsonFileHeader(kManifestFile);
    root.insert(key("line"), manifest.line);
    QJsonArray devices;
    for (const LineManifestEntry& entry : manifest.devices) devices.append(entryToJson(entry));
    root.insert(key("devices"), devices);
    return toIndentedJson(root);
}

Result<LineManifest> lineManifestFromJson(const QByteArray& bytes) {
    const Result<QJsonObject> root = parseJsonFile(bytes, kManifestFile);
    if (!root) return root.error();
    JsonReader reader;
    LineManifest manifest;
    manifest.line = reader.string(*root, {}, key("line"), key("line"));
    const QJsonArray devices = reader.array(*root, {}, key("devices"));
    for (int i = 0; i < devices.size() && !reader.failed(); ++i) {
        const QString path = JsonReader::element(key("devices"), i);
        const LineManifestEntry entry = entryFromJson(reader, devices.at(i), path);
        if (!reader.failed() && manifest.find(entry.device))
            reader.fail(path,
                        QCoreApplication::translate("cambench::model", "device %1 appears twice")
                            .arg(entry.device));
        manifest.put(entry);
    }
    if (reader.failed()) return Error::invalidData(reader.problem() + QLatin1Char('.'));
    return manifest;
}

Status saveLineManifest(const QString& path, const LineManifest& manifest) {
    return writeFileAtomically(path, lineManifestToJson(manifest));
}

Result<LineManifest> loadLineManifest(const QString& path) {
    return loadFileWith<LineManifest>(path, lineManifestFromJson);
}

QString sha256Hex(const QByteArray& bytes) {
    return QString::fromLatin1(QCryptographicHash::hash(bytes, QCryptographicHash::Sha256).toHex());
}

}  // namespace cambench
