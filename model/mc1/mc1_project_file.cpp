#include "mc1_project_file.h"

#include "model/atomic_file.h"
#include "model/file_read.h"
#include "model/json_file.h"
#include "model/json_reader.h"
#include "model/mc1/mc1_family_id.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QRegularExpression>
#include <QSet>

namespace cambench {

namespace {

const JsonFileType kProjectFile{"cambench-mc1-project", kMc1ProjectFormatVersion, "MC-1 project",
                                mc1FamilyId.latin1()};

QString key(const char* text) {
    return QString::fromLatin1(text);
}

QJsonArray toJson(const QList<Mc1NamedValue>& entries) {
    QJsonArray array;
    for (const Mc1NamedValue& entry : entries) {
        QJsonObject object{{key("point"), entry.point}, {key("name"), entry.name}};
        if (entry.value) object.insert(key("value"), *entry.value);
        array.append(object);
    }
    return array;
}

QList<Mc1NamedValue> readEntries(JsonReader& reader, const QJsonObject& root, const char* member,
                                 const QRegularExpression& pattern, const QString& expected) {
    QList<Mc1NamedValue> entries;
    QSet<QString> seen;
    const QJsonArray array = reader.array(root, {}, key(member));
    for (int i = 0; i < array.size() && !reader.failed(); ++i) {
        const QString path = JsonReader::element(key(member), i);
        const QJsonObject object = reader.objectValue(array.at(i), path);
        Mc1NamedValue entry;
        entry.point = reader
                          .string(object, path, key("point"),
                                  QCoreApplication::translate("cambench::model", "point"))
                          .toUpper();
        entry.name = reader.string(object, path, key("name"),
                                   QCoreApplication::translate("cambench::model", "name"));
        if (reader.failed()) break;
        if (!pattern.match(entry.point).hasMatch()) {
            reader.fail(JsonReader::member(path, key("point")),
                        QCoreApplication::translate("cambench::model", "\"%1\" is not %2")
                            .arg(entry.point, expected));
            break;
        }
        if (seen.contains(entry.point)) {
            reader.fail(path, QCoreApplication::translate("cambench::model", "%1 a second time")
                                  .arg(entry.point));
            break;
        }
        seen.insert(entry.point);
        if (object.contains(key("value")))
            entry.value = reader.integer(
                object, path, key("value"), QCoreApplication::translate("cambench::model", "value"),
                std::numeric_limits<qint32>::min(), std::numeric_limits<qint32>::max());
        entries << entry;
    }
    return entries;
}

}  // namespace

QByteArray mc1ProjectToJson(const Mc1Project& project) {
    QJsonObject root = jsonFileHeader(kProjectFile);
    root.insert(key("variant"), project.variant);
    root.insert(key("variables"), toJson(project.variables));
    root.insert(key("flags"), toJson(project.flags));
    return toIndentedJson(root);
}

Result<Mc1Project> mc1ProjectFromJson(const QByteArray& bytes) {
    const Result<QJsonObject> parsed = parseJsonFile(bytes, kProjectFile);
    if (!parsed) return parsed.error();
    JsonReader reader;
    Mc1Project project;
    project.variant =
        reader.string(*parsed, {}, key("variant"),
                      QCoreApplication::translate("cambench::model", "controller variant"));
    static const QRegularExpression variants(QStringLiteral("^(auto|mc(100|200)v[12])$"));
    if (!reader.failed() && !variants.match(project.variant).hasMatch())
        reader.fail(key("variant"), QCoreApplication::translate(
                                        "cambench::model",
                                        "\"%1\" is none of auto, mc100v1, mc100v2, mc200v1, "
                                        "mc200v2")
                                        .arg(project.variant));
    static const QRegularExpression variable(QStringLiteral("^V\\d{1,5}$"));
    static const QRegularExpression flag(QStringLiteral("^[MEA]\\d{1,5}$"));
    project.variables =
        readEntries(reader, *parsed, "variables", variable,
                    QCoreApplication::translate("cambench::model", "a variable such as V12"));
    project.flags = readEntries(
        reader, *parsed, "flags", flag,
        QCoreApplication::translate("cambench::model", "a flag, input or output such as M2327"));
    if (reader.failed()) return Error::invalidData(reader.problem() + QLatin1Char('.'));
    return project;
}

Status saveMc1Project(const QString& path, const Mc1Project& project) {
    return writeFileAtomically(path, mc1ProjectToJson(project), FileAccess::Default);
}

Result<Mc1Project> loadMc1Project(const QString& path) {
    const Result<QByteArray> bytes = readFileBytes(path);
    if (!bytes) return bytes.error();
    Result<Mc1Project> project = mc1ProjectFromJson(*bytes);
    if (!project) return inFile(path, project.error());
    return project;
}

}  // namespace cambench
