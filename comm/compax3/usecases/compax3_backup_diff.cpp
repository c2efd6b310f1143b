// The Compax3's differences object by object, with the objects' names.
#include "compax3_parameters.h"

#include "model/compax3/compax3_value.h"

#include <QCoreApplication>

#include <map>

namespace cambench::usecases {

namespace {

QString labelOf(const Compax3ObjectId& id, const QString& name) {
    return name.isEmpty() ? id.text() : QStringLiteral("%1 %2").arg(id.text(), name);
}

BackupDifference objectItem(const Compax3ObjectId& id, const QString& name, ChangeKind kind,
                            const QString& before, const QString& after) {
    return {{},
            id.text(),
            name,
            before,
            after,
            kind,
            QStringLiteral("%1 %2").arg(labelOf(id, name), changeText(kind, before, after))};
}

}  // namespace

QString nameIn(const Compax3Dictionary& dictionary, const Compax3ObjectId& id) {
    const Compax3ObjectInfo* info = dictionary.find(id);
    return info ? info->name : QString();
}

QString nameOf(const Compax3ParameterSet& set, const Compax3Dictionary& dictionary,
               const Compax3ObjectId& id) {
    for (const Compax3ParameterValue& value : set.values)
        if (value.id == id && !value.name.isEmpty()) return value.name;
    return nameIn(dictionary, id);
}

BackupDifference compax3ObjectDifference(const Compax3Difference& difference, const QString& name) {
    const QString notOnDrive =
        QCoreApplication::translate("cambench::usecases", "not on the drive it was read from");
    if (difference.absentInFile) {
        BackupDifference item =
            objectItem(difference.id, name, ChangeKind::Added, {},
                       difference.error.isEmpty() ? difference.driveValue : difference.error);
        item.text +=
            QStringLiteral(" (%1: %2)")
                .arg(QCoreApplication::translate("cambench::usecases", "the file's"), notOnDrive);
        return item;
    }
    if (!difference.error.isEmpty())
        return objectItem(difference.id, name, ChangeKind::Changed, difference.fileValue,
                          difference.error);
    return objectItem(difference.id, name, ChangeKind::Changed, difference.fileValue,
                      difference.driveValue);
}

QList<BackupDifference> compax3ComparisonItems(const Compax3Comparison& comparison,
                                               const Compax3ParameterSet& set,
                                               const Compax3Dictionary& dictionary) {
    QList<BackupDifference> items;
    for (const Compax3Difference& difference : comparison.differences)
        items << compax3ObjectDifference(difference, nameOf(set, dictionary, difference.id));
    return items;
}

QList<BackupDifference> diffCompax3Sets(const Compax3ParameterSet& before,
                                        const Compax3ParameterSet& after,
                                        const Compax3Dictionary& dictionary) {
    QList<BackupDifference> items;
    const QString drive = QCoreApplication::translate("cambench::usecases", "drive");
    if (before.drive.info != after.drive.info)
        items << BackupDifference{
            {},
            drive,
            QStringLiteral("info"),
            before.drive.info,
            after.drive.info,
            ChangeKind::Changed,
            QStringLiteral("%1 %2").arg(
                drive, changeText(ChangeKind::Changed, before.drive.info, after.drive.info))};
    // By object; an object absent on a drive counts as a value of its own.
    const QString absent = QCoreApplication::translate("cambench::usecases", "not on the drive");
    std::map<Compax3ObjectId, std::pair<std::optional<QString>, std::optional<QString>>> objects;
    for (const Compax3ParameterValue& value : before.values) objects[value.id].first = value.value;
    for (const Compax3ObjectId& id : before.absent) objects[id].first = absent;
    for (const Compax3ParameterValue& value : after.values) objects[value.id].second = value.value;
    for (const Compax3ObjectId& id : after.absent) objects[id].second = absent;
    for (const auto& [id, values] : objects) {
        const QString name = nameOf(after, dictionary, id).isEmpty()
                                 ? nameOf(before, dictionary, id)
                                 : nameOf(after, dictionary, id);
        const auto& [old, now] = values;
        if (!old)
            items << objectItem(id, name, ChangeKind::Added, {}, *now);
        else if (!now)
            items << objectItem(id, name, ChangeKind::Removed, *old, {});
        else if (!compax3SameValue(*old, *now))
            items << objectItem(id, name, ChangeKind::Changed, *old, *now);
    }
    return items;
}

}  // namespace cambench::usecases
