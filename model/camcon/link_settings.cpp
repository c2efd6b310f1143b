#include "link_settings.h"

#include <QCoreApplication>

namespace cambench {

const QStringList& linkSettingKeys() {
    static const QStringList keys{QStringLiteral("deviceNumber"), QStringLiteral("protocol")};
    return keys;
}

bool isLinkSetting(const QString& key) {
    return linkSettingKeys().contains(key);
}

QString linkSettingsText(const SystemSettings& settings) {
    QStringList parts;
    for (const QString& key : linkSettingKeys()) {
        if (!settings.contains(key)) continue;
        const SettingSpec* spec = findSetting(key);
        const qint64 value = settings.value(key).toLongLong();
        QString text = QString::number(value);
        for (const SettingChoice& choice : spec ? spec->choices : QList<SettingChoice>()) {
            if (choice.value == value) text = QCoreApplication::translate("Settings", choice.label);
        }
        const QString label = spec ? QCoreApplication::translate("Settings", spec->label) : key;
        parts << QStringLiteral("%1 %2").arg(label, text);
    }
    return parts.join(QLatin1String(", "));
}

}  // namespace cambench
