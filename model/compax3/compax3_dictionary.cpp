#include "compax3_dictionary.h"

#include "compax3_builtin_objects.h"

#include "model/compax3/compax3_family_id.h"
#include "model/file_read.h"
#include "model/json_file.h"
#include "model/json_reader.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QRegularExpression>

namespace cambench {

namespace {

const JsonFileType kDictionaryFile{"cambench-compax3-dictionary", 1, "Compax3 object dictionary",
                                   compax3FamilyId.latin1()};

// The line of the file where object `position` of "objects" starts: a
// problem with its content is reported there.
int lineOfObject(const QByteArray& bytes, int position) {
    int seen = -1;
    const int arrayStart = int(bytes.indexOf("\"objects\""));
    int depth = 0;
    bool inString = false;
    for (int i = arrayStart < 0 ? 0 : arrayStart; i < bytes.size(); ++i) {
        const char c = bytes.at(i);
        if (inString) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
            continue;
        }
        if (c == '"') inString = true;
        if (c == '[' || c == '{') {
            if (c == '{' && depth == 1 && ++seen == position)
                return int(bytes.left(i).count('\n')) + 1;
            ++depth;
        }
        if (c == ']' || c == '}') --depth;
    }
    return 1;
}

std::optional<Compax3Access> accessFromKey(const QString& key) {
    if (key == QLatin1String("ro")) return Compax3Access::ReadOnly;
    if (key == QLatin1String("rw")) return Compax3Access::ReadWrite;
    if (key == QLatin1String("wo")) return Compax3Access::WriteOnly;
    if (key == QLatin1String("cmd")) return Compax3Access::Command;
    return std::nullopt;
}

std::optional<double> optionalNumber(JsonReader& reader, const QJsonObject& object,
                                     const QString& path, const QString& key) {
    const QJsonValue value = object.value(key);
    if (value.isUndefined() || value.isNull()) return std::nullopt;
    if (!value.isDouble()) {
        reader.fail(JsonReader::member(path, key),
                    QCoreApplication::translate("cambench::model", "not a number"));
        return std::nullopt;
    }
    return value.toDouble();
}

Compax3ObjectInfo readObject(JsonReader& reader, const QJsonObject& object, const QString& path) {
    Compax3ObjectInfo info;
    const QString number = reader.string(object, path, QStringLiteral("object"),
                                         QCoreApplication::translate("cambench::model", "object"));
    if (reader.failed()) return info;
    const Result<Compax3ObjectId> id = parseCompax3Object(number);
    if (!id) {
        reader.fail(JsonReader::member(path, QStringLiteral("object")), id.error().message);
        return info;
    }
    info.id = *id;
    info.name = reader.string(object, path, QStringLiteral("name"),
                              QCoreApplication::translate("cambench::model", "name"));
    const QString type = reader.string(object, path, QStringLiteral("type"),
                                       QCoreApplication::translate("cambench::model", "type"));
    const QString access = reader.string(object, path, QStringLiteral("access"),
                                         QCoreApplication::translate("cambench::model", "access"));
    if (reader.failed()) return info;
    const std::optional<Compax3Type> typeValue = compax3TypeFromKey(type);
    if (!typeValue) {
        reader.fail(
            JsonReader::member(path, QStringLiteral("type")),
            QCoreApplication::translate("cambench::model", "\"%1\" is not integer, real or text")
                .arg(type));
        return info;
    }
    info.type = *typeValue;
    const std::optional<Compax3Access> accessValue = accessFromKey(access);
    if (!accessValue) {
        reader.fail(
            JsonReader::member(path, QStringLiteral("access")),
            QCoreApplication::translate("cambench::model", "\"%1\" is not ro, rw, wo or cmd")
                .arg(access));
        return info;
    }
    info.access = *accessValue;
    info.unit = object.value(QStringLiteral("unit")).toString();
    info.group = object.value(QStringLiteral("group")).toString();
    info.help = object.value(QStringLiteral("help")).toString();
    info.range.min = optionalNumber(reader, object, path, QStringLiteral("min"));
    info.range.max = optionalNumber(reader, object, path, QStringLiteral("max"));
    if (!reader.failed() && info.range.min && info.range.max && *info.range.min > *info.range.max)
        reader.fail(path, QCoreApplication::translate("cambench::model", "min is above max"));
    if (info.group.isEmpty()) info.group = QCoreApplication::translate("cambench::model", "Other");
    // "de": {"name": …, "group": …, "help": …}: the words in another language.
    static const QRegularExpression languageCode(QStringLiteral("^[a-z]{2}$"));
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (!languageCode.match(it.key()).hasMatch()) continue;
        if (!it.value().isObject()) {
            reader.fail(JsonReader::member(path, it.key()),
                        QCoreApplication::translate("cambench::model",
                                                    "not an object of name, group and help"));
            return info;
        }
        const QJsonObject texts = it.value().toObject();
        info.translated.insert(it.key(),
                               Compax3Texts{texts.value(QStringLiteral("name")).toString(),
                                            texts.value(QStringLiteral("group")).toString(),
                                            texts.value(QStringLiteral("help")).toString()});
    }
    return info;
}

}  // namespace

Result<Compax3Dictionary> Compax3Dictionary::fromJson(const QByteArray& bytes) {
    const Result<QJsonObject> root = parseJsonFile(bytes, kDictionaryFile);
    if (!root) return root.error();
    JsonReader reader;
    const QJsonArray objects = reader.array(*root, QString(), QStringLiteral("objects"));
    Compax3Dictionary dictionary;
    for (int i = 0; i < objects.size() && !reader.failed(); ++i) {
        const QString path = JsonReader::element(QStringLiteral("objects"), i);
        const QJsonObject object = reader.objectValue(objects.at(i), path);
        if (reader.failed()) break;
        const Compax3ObjectInfo info = readObject(reader, object, path);
        if (!reader.failed() && dictionary.m_index.contains(info.id))
            reader.fail(path,
                        QCoreApplication::translate("cambench::model", "object %1 a second time")
                            .arg(info.id.text()));
        if (reader.failed()) {
            return Error::invalidData(QCoreApplication::translate("cambench::model", "line %1: %2.")
                                          .arg(lineOfObject(bytes, i))
                                          .arg(reader.problem()));
        }
        dictionary.m_index.insert(info.id, int(dictionary.m_objects.size()));
        dictionary.m_objects << info;
    }
    if (reader.failed()) return Error::invalidData(reader.problem() + QLatin1Char('.'));
    dictionary.m_refusals = compax3RefusalsFromJson(bytes);
    // A file of objects only keeps the shipped meanings.
    if (dictionary.m_refusals.isEmpty()) dictionary.m_refusals = compax3Refusals();
    return dictionary;
}

Result<Compax3Dictionary> Compax3Dictionary::load(const QString& path) {
    const Result<Compax3Dictionary> parsed = loadFileWith(path, &Compax3Dictionary::fromJson);
    if (!parsed) return parsed.error();
    Compax3Dictionary dictionary = *parsed;
    dictionary.m_source = path;
    return dictionary;
}

const Compax3Dictionary& Compax3Dictionary::builtin() {
    static const Compax3Dictionary dictionary = [] {
        Result<Compax3Dictionary> parsed = fromJson(compax3BuiltinObjectsJson());
        Q_ASSERT_X(parsed, "Compax3Dictionary::builtin", "the shipped dictionary is broken");
        Compax3Dictionary builtIn = parsed ? *parsed : Compax3Dictionary();
        builtIn.m_source = QCoreApplication::translate("cambench::model", "built in");
        return builtIn;
    }();
    return dictionary;
}

namespace {

QString inLanguage(const Compax3ObjectInfo& info, const QString& language,
                   QString Compax3Texts::*member, const QString& english) {
    const auto it = info.translated.constFind(language);
    if (it == info.translated.cend() || ((*it).*member).isEmpty()) return english;
    return (*it).*member;
}

}  // namespace

QString Compax3ObjectInfo::nameIn(const QString& language) const {
    return inLanguage(*this, language, &Compax3Texts::name, name);
}

QString Compax3ObjectInfo::groupIn(const QString& language) const {
    return inLanguage(*this, language, &Compax3Texts::group, group);
}

QString Compax3ObjectInfo::helpIn(const QString& language) const {
    return inLanguage(*this, language, &Compax3Texts::help, help);
}

const Compax3ObjectInfo* Compax3Dictionary::find(const Compax3ObjectId& id) const {
    const auto it = m_index.constFind(id);
    return it == m_index.cend() ? nullptr : &m_objects.at(*it);
}

QStringList Compax3Dictionary::groups() const {
    QStringList groups;
    for (const Compax3ObjectInfo& info : m_objects)
        if (!groups.contains(info.group)) groups << info.group;
    return groups;
}

QList<Compax3ObjectId> Compax3Dictionary::parameters() const {
    QList<Compax3ObjectId> ids;
    for (const Compax3ObjectInfo& info : m_objects)
        if (info.parameter()) ids << info.id;
    return ids;
}

namespace {

// The objects that start, stop or store on a Compax3 whatever a dictionary
// says (comm/compax3/README.md C1, C3): the control word and the set stores.
constexpr Compax3ObjectId kControlWord{1100, 3};
constexpr int kStoreSetIndex = 1904;

bool marked(const Compax3Dictionary& dictionary, const Compax3ObjectId& id, Compax3Access access) {
    const Compax3ObjectInfo* info = dictionary.find(id);
    return info && info->access == access;
}

}  // namespace

bool compax3IsControlWord(const Compax3Dictionary& inUse, const Compax3ObjectId& id) {
    return id == kControlWord || marked(Compax3Dictionary::builtin(), id, Compax3Access::Command) ||
           marked(inUse, id, Compax3Access::Command);
}

QString compax3NeverFromAFile(const Compax3Dictionary& inUse, const Compax3ObjectId& id) {
    if (compax3IsControlWord(inUse, id))
        return QCoreApplication::translate("cambench::model",
                                           "%1 is a control word: a file never starts or stops the "
                                           "axis (use the Motion page "
                                           "or c3 enable/jog/move/stop)")
            .arg(id.text());
    if (id.index == kStoreSetIndex ||
        marked(Compax3Dictionary::builtin(), id, Compax3Access::WriteOnly) ||
        marked(inUse, id, Compax3Access::WriteOnly))
        return QCoreApplication::translate(
                   "cambench::model", "%1 is a function, not a value: a file never triggers it")
            .arg(id.text());
    return {};
}

Result<QString> compax3WireValueFor(const Compax3Dictionary& dictionary, const Compax3ObjectId& id,
                                    const QString& typed) {
    const Compax3ObjectInfo* info = dictionary.find(id);
    if (!info) {
        const bool quoted = typed.trimmed().startsWith(QLatin1Char('"'));
        return compax3WireValue(typed, quoted ? Compax3Type::Text : Compax3Type::Real);
    }
    if (!info->writable())
        return Error::usage(QCoreApplication::translate("cambench::model", "%1 (%2) is read-only")
                                .arg(id.text(), info->name));
    const Result<QString> wire = compax3WireValue(typed, info->type, info->range);
    if (!wire)
        return Error::usage(
            QStringLiteral("%1 (%2): %3").arg(id.text(), info->name, wire.error().message));
    return wire;
}

}  // namespace cambench
