#include "settings_file.h"

#include <QCoreApplication>

#include "model/camcon/camcon_family_id.h"
#include "model/file_read.h"
#include "model/json_file.h"

#include <limits>

namespace cambench {

namespace {

const JsonFileType kSettingsFile{"cambench-settings", kSettingsFileFormatVersion, "settings file",
                                 camconFamilyId.latin1()};

}  // namespace

QJsonObject settingsToJson(const SystemSettings& settings) {
    QJsonObject object;
    for (auto it = settings.cbegin(); it != settings.cend(); ++it) {
        const SettingSpec* spec = findSetting(it.key());
        if (spec && spec->kind == SettingKind::Text)
            object.insert(it.key(), it->toString());
        else
            object.insert(it.key(), it->toLongLong());
    }
    return object;
}

SystemSettings settingsFromJson(JsonReader& reader, const QJsonObject& object,
                                const QString& path) {
    SystemSettings settings;
    for (auto it = object.constBegin(); it != object.constEnd() && !reader.failed(); ++it) {
        const QString where = JsonReader::member(path, it.key());
        const SettingSpec* spec = findSetting(it.key());
        if (!spec) {
            reader.fail(where,
                        QCoreApplication::translate("cambench::model", "there is no such setting"));
            break;
        }
        if (spec->kind == SettingKind::Text) {
            if (!it->isString()) {
                reader.fail(where, QCoreApplication::translate("cambench::model",
                                                               "the value is not a text"));
                break;
            }
            settings.insert(it.key(), it->toString());
        } else {
            // Any whole number: a device may hold values outside the range
            // the manual gives; validateSettings() says so, loading keeps them.
            settings.insert(
                it.key(),
                reader.integerValue(
                    *it, where, QCoreApplication::translate("cambench::model", "the value"),
                    std::numeric_limits<qint64>::min(), std::numeric_limits<qint64>::max()));
        }
    }
    return settings;
}

QByteArray settingsFileToJson(const SystemSettings& settings) {
    QJsonObject root = jsonFileHeader(kSettingsFile);
    root.insert(QStringLiteral("settings"), settingsToJson(settings));
    return toIndentedJson(root);
}

Result<SystemSettings> settingsFileFromJson(const QByteArray& bytes) {
    const Result<QJsonObject> root = parseJsonFile(bytes, kSettingsFile);
    if (!root) return root.error();
    JsonReader reader;
    const QString key = QStringLiteral("settings");
    SystemSettings settings = settingsFromJson(reader, reader.object(*root, {}, key), key);
    if (reader.failed()) return Error::invalidData(reader.problem() + QLatin1Char('.'));
    return settings;
}

Result<SystemSettings> loadSettingsFile(const QString& path) {
    return loadFileWith<SystemSettings>(path, settingsFileFromJson);
}

}  // namespace cambench
