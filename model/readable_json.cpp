#include "readable_json.h"

#include <QJsonArray>
#include <QJsonDocument>

#include <iterator>

namespace cambench {

namespace {

bool isPlain(const QJsonValue& value) {
    return !value.isArray() && !value.isObject();
}

// Holds no object at any depth: stays on one line as an array element.
bool holdsNoObject(const QJsonValue& value) {
    if (value.isObject()) {
        const QJsonObject object = value.toObject();
        for (auto it = object.constBegin(); it != object.constEnd(); ++it)
            if (it->isObject() || (it->isArray() && !holdsNoObject(*it))) return false;
        return true;
    }
    if (value.isArray()) {
        for (const QJsonValue& element : value.toArray())
            if (element.isObject() || !holdsNoObject(element)) return false;
    }
    return true;
}

QByteArray compact(const QJsonValue& value) {
    if (value.isObject()) return QJsonDocument(value.toObject()).toJson(QJsonDocument::Compact);
    if (value.isArray()) return QJsonDocument(value.toArray()).toJson(QJsonDocument::Compact);
    // A plain value: the array's compact text without its brackets.
    const QByteArray text = QJsonDocument(QJsonArray{value}).toJson(QJsonDocument::Compact);
    return text.mid(1, text.size() - 2);
}

void write(const QJsonValue& value, int depth, QByteArray& out);

void writeObject(const QJsonObject& object, int depth, QByteArray& out) {
    if (object.isEmpty()) {
        out += "{}";
        return;
    }
    const QByteArray indent((depth + 1) * 4, ' ');
    out += "{\n";
    for (auto it = object.constBegin(); it != object.constEnd(); ++it) {
        out += indent + compact(it.key()) + ": ";
        write(*it, depth + 1, out);
        if (std::next(it) != object.constEnd()) out += ',';
        out += '\n';
    }
    out += QByteArray(depth * 4, ' ') + '}';
}

void writeArray(const QJsonArray& array, int depth, QByteArray& out) {
    bool plain = true;
    for (const QJsonValue& element : array) plain = plain && isPlain(element);
    if (plain) {
        out += compact(array);
        return;
    }
    const QByteArray indent((depth + 1) * 4, ' ');
    out += "[\n";
    for (qsizetype i = 0; i < array.size(); ++i) {
        out += indent;
        if (holdsNoObject(array.at(i)))
            out += compact(array.at(i));
        else
            write(array.at(i), depth + 1, out);
        if (i + 1 < array.size()) out += ',';
        out += '\n';
    }
    out += QByteArray(depth * 4, ' ') + ']';
}

void write(const QJsonValue& value, int depth, QByteArray& out) {
    if (value.isObject())
        writeObject(value.toObject(), depth, out);
    else if (value.isArray())
        writeArray(value.toArray(), depth, out);
    else
        out += compact(value);
}

}  // namespace

QByteArray toReadableJson(const QJsonObject& object) {
    QByteArray out;
    writeObject(object, 0, out);
    out += '\n';
    return out;
}

}  // namespace cambench
