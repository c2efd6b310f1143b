#include "json_file.h"

#include "json_reader.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QJsonDocument>
#include <QJsonParseError>

namespace cambench {

namespace {

int lineAt(const QByteArray& bytes, int offset) {
    return int(bytes.left(offset).count('\n')) + 1;
}

}  // namespace

Result<QJsonObject> parseJsonFile(const QByteArray& bytes, const JsonFileType& type) {
    const QString noun = QString::fromLatin1(type.noun);
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(bytes, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        return Error::invalidData(
            QCoreApplication::translate(
                "cambench::model",
                "This is not a CamBench %1: it is not valid JSON (line %2: %3). "
                "The file may be truncated or damaged.")
                .arg(noun)
                .arg(lineAt(bytes, parseError.offset))
                .arg(parseError.errorString()));
    }
    if (!document.isObject()) {
        return Error::invalidData(
            QCoreApplication::translate("cambench::model",
                                        "This is not a CamBench %1: the JSON holds no object.")
                .arg(noun));
    }
    const QJsonObject root = document.object();
    const QString expected = QString::fromLatin1(type.format);
    const QJsonValue format = root.value(QStringLiteral("format"));
    if (format.toString() != expected) {
        return Error::invalidData(
            QCoreApplication::translate(
                "cambench::model",
                "This is not a CamBench %1: its \"format\" is %2, expected \"%3\".")
                .arg(noun,
                     format.isString() ? QLatin1Char('"') + format.toString() + QLatin1Char('"')
                                       : QCoreApplication::translate("cambench::model", "missing"),
                     expected));
    }
    JsonReader reader;
    const qint64 version =
        reader.integer(root, QString(), QStringLiteral("version"),
                       QCoreApplication::translate("cambench::model", "the format version"), 1,
                       std::numeric_limits<qint32>::max());
    if (reader.failed()) return Error::invalidData(reader.problem() + QLatin1Char('.'));
    if (version > type.version) {
        return Error::invalidData(
            QCoreApplication::translate(
                "cambench::model",
                "This %1 was written by a newer CamBench (format version %2); this "
                "CamBench reads version %3. Open it with a newer CamBench.")
                .arg(noun)
                .arg(version)
                .arg(type.version));
    }
    const QJsonValue family = root.value(QStringLiteral("family"));
    if (type.family && !family.isUndefined() && family.toString() != QLatin1String(type.family)) {
        return Error::invalidData(
            QCoreApplication::translate(
                "cambench::model",
                "This %1 is for devices of the family \"%2\", not \"%3\": nothing was loaded. "
                "Open it where a device of that family is connected.")
                .arg(noun, family.isString() ? family.toString() : family.toVariant().toString(),
                     QString::fromLatin1(type.family)));
    }
    return root;
}

QJsonObject jsonFileHeader(const JsonFileType& type) {
    QJsonObject header;
    header.insert(QStringLiteral("format"), QString::fromLatin1(type.format));
    header.insert(QStringLiteral("version"), type.version);
    if (type.family) header.insert(QStringLiteral("family"), QString::fromLatin1(type.family));
    return header;
}

QByteArray toIndentedJson(const QJsonObject& object) {
    return QJsonDocument(object).toJson(QJsonDocument::Indented);
}

namespace {

QByteArray hashOf(const QJsonObject& withoutHash) {
    return QCryptographicHash::hash(QJsonDocument(withoutHash).toJson(QJsonDocument::Compact),
                                    QCryptographicHash::Sha256)
        .toHex();
}

}  // namespace

void sealWithHash(QJsonObject& root) {
    root.insert(QStringLiteral("sha256"), QString::fromLatin1(hashOf(root)));
}

Status takeCheckedHash(QJsonObject& root) {
    const QJsonValue stored = root.take(QStringLiteral("sha256"));
    if (!stored.isString())
        return Error::invalidData(
            QCoreApplication::translate("cambench::model", "sha256: the checksum is missing."));
    if (stored.toString().toLatin1().toLower() != hashOf(root))
        return Error::invalidData(
            QCoreApplication::translate("cambench::model",
                                        "The file was changed or damaged: its SHA-256 "
                                        "checksum does not match its content. Do not "
                                        "restore it; take a new backup."));
    return success();
}

}  // namespace cambench
