#include "compax3_refusals.h"

#include "compax3_builtin_objects.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace cambench {

namespace {

// {"refusals":[{"code":"0002","meaning":"…","de":"…","absent":true},…]}
QList<Compax3RefusalMeaning> readRefusals(const QByteArray& json) {
    QList<Compax3RefusalMeaning> table;
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

const Compax3RefusalMeaning* find(int code) {
    for (const Compax3RefusalMeaning& entry : compax3Refusals())
        if (entry.code == code) return &entry;
    return nullptr;
}

}  // namespace

const QList<Compax3RefusalMeaning>& compax3Refusals() {
    static const QList<Compax3RefusalMeaning> table = readRefusals(compax3BuiltinObjectsJson());
    return table;
}

QString compax3RefusalMeaning(int code) {
    const Compax3RefusalMeaning* entry = find(code);
    if (!entry) return {};
    // The UI's language is the one its installed translation is in (a
    // German PC's locale alone does not make the English CLI German).
    const bool german =
        QCoreApplication::translate("cambench::model", "language of the Compax3 refusals: en") ==
        QLatin1String("de");
    return german && !entry->german.isEmpty() ? entry->german : entry->meaning;
}

bool compax3RefusalSaysAbsent(int code) {
    const Compax3RefusalMeaning* entry = find(code);
    return entry && entry->absent;
}

}  // namespace cambench
