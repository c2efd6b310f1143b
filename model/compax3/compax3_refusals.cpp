#include "compax3_refusals.h"

#include "compax3_builtin_objects.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace cambench {

namespace {

const Compax3RefusalMeaning* find(const Compax3RefusalTable& table, int code) {
    for (const Compax3RefusalMeaning& entry : table)
        if (entry.code == code) return &entry;
    return nullptr;
}

}  // namespace

// {"refusals":[{"code":"0002","meaning":"…","de":"…","absent":true},…]}
Compax3RefusalTable compax3RefusalsFromJson(const QByteArray& json) {
    Compax3RefusalTable table;
    const QJsonArray refusals =
        QJsonDocument::fromJson(json).object().value(QStringLiteral("refusals")).toArray();
    for (const QJsonValue& value : refusals) {
        const QJsonObject entry = value.toObject();
        bool ok = false;
        const int code = entry.value(QStringLiteral("code")).toString().toInt(&ok, 16);
        if (!ok) continue;
        table << Compax3RefusalMeaning{code, entry.value(QStringLiteral("meaning")).toString(),
                                       entry.value(QStringLiteral("de")).toString(),
                                       entry.value(QStringLiteral("absent")).toBool()};
    }
    return table;
}

const Compax3RefusalTable& compax3Refusals() {
    static const Compax3RefusalTable table = compax3RefusalsFromJson(compax3BuiltinObjectsJson());
    return table;
}

QString compax3RefusalMeaning(int code) {
    return compax3RefusalMeaning(compax3Refusals(), code);
}

QString compax3RefusalMeaning(const Compax3RefusalTable& table, int code) {
    const Compax3RefusalMeaning* entry = find(table, code);
    if (!entry) return {};
    // The UI's language is the one its installed translation is in (a
    // German PC's locale alone does not make the English CLI German).
    const bool german =
        QCoreApplication::translate("cambench::model", "language of the Compax3 refusals: en") ==
        QLatin1String("de");
    return german && !entry->german.isEmpty() ? entry->german : entry->meaning;
}

bool compax3RefusalSaysAbsent(int code) {
    return compax3RefusalSaysAbsent(compax3Refusals(), code);
}

bool compax3RefusalSaysAbsent(const Compax3RefusalTable& table, int code) {
    const Compax3RefusalMeaning* entry = find(table, code);
    return entry && entry->absent;
}

}  // namespace cambench
