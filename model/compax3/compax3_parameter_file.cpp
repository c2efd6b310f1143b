#include "compax3_parameter_file.h"

#include "model/atomic_file.h"
#include "model/compax3/compax3_family_id.h"
#include "model/file_read.h"
#include "model/json_file.h"
#include "model/json_reader.h"
#include "model/readable_json.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QSet>

#include <algorithm>

namespace cambench {

namespace {

const JsonFileType kParameterFile{"cambench-compax3-parameters", kCompax3ParameterFormatVersion,
                                  "Compax3 parameter file", compax3FamilyId.latin1()};
const QLatin1String kToolPrefix("CamBench ");

QString key(const char* text) {
    return QString::fromLatin1(text);
}

}  // namespace

QString Compax3Identity::type() const {
    const QStringList words = info.simplified().split(QLatin1Char(' '));
    return words.size() > 1 ? words.at(1) : QString();
}

DeviceIdentity Compax3Identity::deviceIdentity() const {
    DeviceIdentity identity;
    if (serial.isEmpty()) return identity;
    identity.set(QStringLiteral("serial"), serial);
    identity.set(QStringLiteral("type"), type());
    return identity;
}

QByteArray compax3ParametersToJson(const Compax3ParameterSet& set) {
    QJsonObject root = jsonFileHeader(kParameterFile);
    root.insert(key("drive"), QJsonObject{{key("info"), set.drive.info},
                                          {key("serial"), set.drive.serial},
                                          {key("type"), set.drive.type()}});
    root.insert(key("taken"), set.taken.toUTC().toString(Qt::ISODateWithMs));
    root.insert(key("tool"), kToolPrefix + set.toolVersion);
    QList<Compax3ParameterValue> values = set.values;
    std::stable_sort(values.begin(), values.end(),
                     [](const auto& a, const auto& b) { return a.id < b.id; });
    QJsonArray objects;
    for (const Compax3ParameterValue& value : values)
        objects.append(value.name.isEmpty() ? QJsonArray{value.id.text(), value.value}
                                            : QJsonArray{value.id.text(), value.value, value.name});
    root.insert(key("objects"), objects);
    if (!set.absent.isEmpty()) {
        QList<Compax3ObjectId> absent = set.absent;
        std::sort(absent.begin(), absent.end());
        QJsonArray ids;
        for (const Compax3ObjectId& id : absent) ids.append(id.text());
        root.insert(key("absent"), ids);
    }
    sealWithHash(root);
    // One object a line: a diff of two files shows the objects that differ.
    return toReadableJson(root);
}

Result<Compax3ParameterSet> compax3ParametersFromJson(const QByteArray& bytes) {
    const Result<QJsonObject> parsed = parseJsonFile(bytes, kParameterFile);
    if (!parsed) return parsed.error();
    QJsonObject root = *parsed;
    if (const Status hash = takeCheckedHash(root); !hash) return hash.error();
    JsonReader reader;
    Compax3ParameterSet set;
    const QJsonObject drive = reader.object(root, {}, key("drive"));
    set.drive.info = reader.string(drive, key("drive"), key("info"),
                                   QCoreApplication::translate("cambench::model", "info string"));
    set.drive.serial = drive.value(key("serial")).toString();
    const QString taken = reader.string(
        root, {}, key("taken"), QCoreApplication::translate("cambench::model", "time taken"));
    set.taken = QDateTime::fromString(taken, Qt::ISODateWithMs).toUTC();
    if (!reader.failed() && !set.taken.isValid())
        reader.fail(key("taken"), QCoreApplication::translate(
                                      "cambench::model", "\"%1\" is not an ISO 8601 date and time")
                                      .arg(taken));
    const QString tool = root.value(key("tool")).toString();
    set.toolVersion = tool.startsWith(kToolPrefix) ? tool.mid(kToolPrefix.size()) : tool;
    const QJsonArray objects = reader.array(root, {}, key("objects"));
    QSet<Compax3ObjectId> seen;
    for (int i = 0; i < objects.size() && !reader.failed(); ++i) {
        const QString path = JsonReader::element(key("objects"), i);
        const QJsonArray pair = objects.at(i).toArray();
        if (pair.size() < 2 || pair.size() > 3 || !pair.at(0).isString() ||
            !pair.at(1).isString() || (pair.size() == 3 && !pair.at(2).isString())) {
            reader.fail(path, QCoreApplication::translate("cambench::model",
                                                          "not [\"object\", \"value\", \"name\"]"));
            break;
        }
        const Result<Compax3ObjectId> id = parseCompax3Object(pair.at(0).toString());
        if (!id) {
            reader.fail(path, id.error().message);
            break;
        }
        if (seen.contains(*id)) {
            reader.fail(path,
                        QCoreApplication::translate("cambench::model", "object %1 a second time")
                            .arg(id->text()));
            break;
        }
        seen.insert(*id);
        set.values << Compax3ParameterValue{*id, pair.at(1).toString(), pair.at(2).toString()};
    }
    const QJsonArray absent = root.value(key("absent")).toArray();
    for (int i = 0; i < absent.size() && !reader.failed(); ++i) {
        const Result<Compax3ObjectId> id = parseCompax3Object(absent.at(i).toString());
        const QString path = JsonReader::element(key("absent"), i);
        if (!id) {
            reader.fail(path, id.error().message);
        } else if (seen.contains(*id)) {
            reader.fail(path, QCoreApplication::translate("cambench::model",
                                                          "object %1 both with a value and absent")
                                  .arg(id->text()));
        } else {
            seen.insert(*id);
            set.absent << *id;
        }
    }
    if (reader.failed()) return Error::invalidData(reader.problem() + QLatin1Char('.'));
    return set;
}

Status saveCompax3Parameters(const QString& path, const Compax3ParameterSet& set) {
    return writeFileAtomically(path, compax3ParametersToJson(set));
}

Result<Compax3ParameterSet> loadCompax3Parameters(const QString& path) {
    return loadFileWith(path, &compax3ParametersFromJson);
}

}  // namespace cambench
