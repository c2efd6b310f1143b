#include "backup_difference.h"

#include <QCoreApplication>

namespace cambench {

QString BackupDifference::line() const {
    return device.isEmpty() ? text : device + QStringLiteral(": ") + text;
}

QString changeText(ChangeKind kind, const QString& oldValue, const QString& newValue) {
    switch (kind) {
        case ChangeKind::Added:
            return QCoreApplication::translate("cambench::model", "%1 added").arg(newValue);
        case ChangeKind::Removed:
            return QCoreApplication::translate("cambench::model", "%1 removed").arg(oldValue);
        case ChangeKind::Changed:
            break;
    }
    return QStringLiteral("%1 → %2").arg(oldValue, newValue);
}

QList<BackupDifference> onDevice(QList<BackupDifference> differences, const QString& device) {
    for (BackupDifference& difference : differences) difference.device = device;
    return differences;
}

}  // namespace cambench
