#include "json_reader.h"

#include <QCoreApplication>

#include <cmath>

namespace cambench {

namespace {

// Doubles hold integers exactly up to 2^53.
constexpr double kExactIntegerLimit = 9007199254740992.0;

}  // namespace

void JsonReader::fail(const QString& path, const QString& what) {
    if (failed()) return;
    m_problem = path.isEmpty() ? what : path + QStringLiteral(": ") + what;
}

QString JsonReader::member(const QString& path, const QString& key) {
    return path.isEmpty() ? key : path + QLatin1Char('.') + key;
}

QString JsonReader::element(const QString& path, int index) {
    return QStringLiteral("%1[%2]").arg(path).arg(index);
}

bool JsonReader::has(const QJsonObject& object, const QString& path, const QString& key) {
    if (failed()) return false;
    if (!object.contains(key)) {
        fail(path, QCoreApplication::translate("cambench::model", "\"%1\" is missing").arg(key));
        return false;
    }
    return true;
}

qint64 JsonReader::integerValue(const QJsonValue& value, const QString& path, const QString& what,
                                qint64 min, qint64 max) {
    if (failed()) return 0;
    const double d = value.toDouble();
    if (!value.isDouble() || !std::isfinite(d) || d != std::trunc(d) ||
        std::abs(d) > kExactIntegerLimit) {
        fail(path,
             QCoreApplication::translate("cambench::model", "%1 is not an integer").arg(what));
        return 0;
    }
    const qint64 v = qint64(d);
    if (v < min || v > max) {
        fail(path, QCoreApplication::translate("cambench::model", "%1 %2 is outside %3..%4")
                       .arg(what)
                       .arg(v)
                       .arg(min)
                       .arg(max));
        return 0;
    }
    return v;
}

qint64 JsonReader::integer(const QJsonObject& object, const QString& path, const QString& key,
                           const QString& what, qint64 min, qint64 max) {
    if (!has(object, path, key)) return 0;
    return integerValue(object.value(key), member(path, key), what, min, max);
}

QString JsonReader::string(const QJsonObject& object, const QString& path, const QString& key,
                           const QString& what) {
    if (!has(object, path, key)) return {};
    const QJsonValue value = object.value(key);
    if (!value.isString()) {
        fail(member(path, key),
             QCoreApplication::translate("cambench::model", "%1 is not a string").arg(what));
        return {};
    }
    return value.toString();
}

bool JsonReader::boolean(const QJsonObject& object, const QString& path, const QString& key,
                         const QString& what) {
    if (!has(object, path, key)) return false;
    const QJsonValue value = object.value(key);
    if (!value.isBool()) {
        fail(member(path, key),
             QCoreApplication::translate("cambench::model", "%1 is not true or false").arg(what));
        return false;
    }
    return value.toBool();
}

QJsonArray JsonReader::array(const QJsonObject& object, const QString& path, const QString& key) {
    if (!has(object, path, key)) return {};
    return arrayValue(object.value(key), member(path, key));
}

QJsonObject JsonReader::object(const QJsonObject& object, const QString& path, const QString& key) {
    if (!has(object, path, key)) return {};
    return objectValue(object.value(key), member(path, key));
}

QJsonObject JsonReader::objectValue(const QJsonValue& value, const QString& path) {
    if (failed()) return {};
    if (!value.isObject()) {
        fail(path, QCoreApplication::translate("cambench::model", "a JSON object is expected"));
        return {};
    }
    return value.toObject();
}

QJsonArray JsonReader::arrayValue(const QJsonValue& value, const QString& path) {
    if (failed()) return {};
    if (!value.isArray()) {
        fail(path, QCoreApplication::translate("cambench::model", "a JSON array is expected"));
        return {};
    }
    return value.toArray();
}

}  // namespace cambench
