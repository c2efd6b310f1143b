#include "machine_backup_folder.h"

#include "model/file_read.h"
#include "model/json_file.h"
#include "model/readable_json.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QRegularExpression>

#ifdef Q_OS_UNIX
#include <pwd.h>
#include <unistd.h>
#endif

namespace cambench {

namespace {

const JsonFileType kManifest{"cambench-machine-backup", 1, "machine backup manifest"};

QString key(const char* name) {
    return QLatin1String(name);
}

QString isoTime(const QDateTime& time) {
    return time.isValid() ? time.toUTC().toString(Qt::ISODateWithMs) : QString();
}

QJsonObject entryJson(const ManifestEntry& entry) {
    QJsonObject object{{key("name"), entry.name},
                       {key("family"), entry.family},
                       {key("file"), entry.file},
                       {key("result"), entry.result}};
    if (entry.identity.known()) object.insert(key("identity"), entry.identity.toJson());
    if (!entry.device.isEmpty()) object.insert(key("device"), entry.device);
    if (!entry.summary.isEmpty()) object.insert(key("summary"), entry.summary);
    if (!entry.incomplete.isEmpty())
        object.insert(key("incomplete"), QJsonArray::fromStringList(entry.incomplete));
    if (!entry.sha256.isEmpty()) object.insert(key("sha256"), entry.sha256);
    if (entry.time.isValid()) object.insert(key("time"), isoTime(entry.time));
    return object;
}

ManifestEntry entryFrom(const QJsonObject& object) {
    ManifestEntry entry;
    entry.name = object.value(key("name")).toString();
    entry.family = object.value(key("family")).toString();
    entry.file = object.value(key("file")).toString();
    // An older manifest held identify()'s text as "identity": not known.
    const Result<DeviceIdentity> identity =
        object.value(key("identity")).isObject()
            ? DeviceIdentity::fromJson(object.value(key("identity")), QString())
            : Result<DeviceIdentity>(DeviceIdentity());
    if (identity) entry.identity = *identity;
    entry.device = object.value(key("device")).toString();
    entry.summary = object.value(key("summary")).toString();
    for (const QJsonValue& line : object.value(key("incomplete")).toArray())
        entry.incomplete << line.toString();
    entry.sha256 = object.value(key("sha256")).toString();
    entry.time = QDateTime::fromString(object.value(key("time")).toString(), Qt::ISODateWithMs);
    entry.result = object.value(key("result")).toString();
    return entry;
}

}  // namespace

QString loginName() {
    for (const char* variable : {"USER", "LOGNAME", "USERNAME"}) {
        const QString name = qEnvironmentVariable(variable);
        if (!name.isEmpty()) return name;
    }
#ifdef Q_OS_UNIX
    if (const passwd* user = getpwuid(geteuid()); user && user->pw_name)
        return QString::fromLocal8Bit(user->pw_name);
#endif
    return QStringLiteral("unknown");
}

const ManifestEntry* MachineManifest::entry(const QString& name) const {
    for (const ManifestEntry& device : devices)
        if (device.name == name) return &device;
    return nullptr;
}

QByteArray manifestJson(const MachineManifest& manifest) {
    QJsonObject root = jsonFileHeader(kManifest);
    root.insert(key("machine"), manifest.machine);
    root.insert(key("operator"), manifest.author.operatorName);
    if (!manifest.author.note.isEmpty()) root.insert(key("note"), manifest.author.note);
    root.insert(key("tool"), manifest.author.tool);
    root.insert(key("revision"), manifest.author.revision);
    if (manifest.started.isValid()) root.insert(key("started"), isoTime(manifest.started));
    if (!manifest.safetyCopyOf.isEmpty()) root.insert(key("safetyCopyOf"), manifest.safetyCopyOf);
    QJsonArray devices;
    for (const ManifestEntry& entry : manifest.devices) devices << entryJson(entry);
    root.insert(key("devices"), devices);
    return toReadableJson(root);
}

Result<MachineManifest> parseManifest(const QByteArray& bytes, const QString& where) {
    const Result<QJsonObject> root = parseJsonFile(bytes, kManifest);
    if (!root) return Error::invalidData(QStringLiteral("%1: %2").arg(where, root.error().message));
    MachineManifest manifest;
    manifest.machine = root->value(key("machine")).toString();
    manifest.author.operatorName = root->value(key("operator")).toString();
    manifest.author.note = root->value(key("note")).toString();
    manifest.author.tool = root->value(key("tool")).toString();
    manifest.author.revision = root->value(key("revision")).toString();
    manifest.started =
        QDateTime::fromString(root->value(key("started")).toString(), Qt::ISODateWithMs);
    manifest.safetyCopyOf = root->value(key("safetyCopyOf")).toString();
    for (const QJsonValue& value : root->value(key("devices")).toArray())
        manifest.devices << entryFrom(value.toObject());
    return manifest;
}

QString deviceFileName(const QString& deviceName) {
    QString name = deviceName;
    name.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9._-]")), QStringLiteral("_"));
    return name + QStringLiteral(".json");
}

QString fileSha256(const QString& path) {
    const Result<QByteArray> bytes = readFileBytes(path);
    return bytes ? QString::fromLatin1(
                       QCryptographicHash::hash(*bytes, QCryptographicHash::Sha256).toHex())
                 : QString();
}

bool stillSaved(const ManifestEntry& entry, const QString& dir) {
    return entry.saved() && !entry.sha256.isEmpty() &&
           fileSha256(QDir(dir).filePath(entry.file)) == entry.sha256;
}

QString safetyFolderPath(const QString& dir, const QDateTime& utc) {
    const QString base = QDir::cleanPath(QFileInfo(dir).absoluteFilePath()) +
                         QStringLiteral(".safety-") +
                         utc.toUTC().toString(QStringLiteral("yyyyMMddTHHmmssZ"));
    QString path = base;
    for (int n = 2; QFileInfo::exists(path); ++n) path = base + QStringLiteral("-%1").arg(n);
    return path;
}

}  // namespace cambench
