#include "ascii_camcon.h"

#include <QCoreApplication>
#include "ascii_support.h"
#include "settings_commands.h"

namespace cambench::comm {

using namespace client;

namespace {

bool isTextKey(const QString& key) {
    const SettingSpec* spec = findSetting(key);
    return spec && spec->kind == SettingKind::Text;
}

bool writable(const QString& key) {
    const SettingSpec* spec = findSetting(key);
    return spec && !spec->readOnly;
}

bool sameValue(const QString& key, const QVariant& a, const QVariant& b) {
    if (isTextKey(key)) return a.toString() == b.toString();
    return a.toLongLong() == b.toLongLong();
}

// Whether `settings` asks for a value of `key` other than the device's.
bool changes(const SystemSettings& settings, const SystemSettings& current, const QString& key) {
    return settings.contains(key) && writable(key) &&
           (!current.contains(key) || !sameValue(key, settings.value(key), current.value(key)));
}

// The value to write: the requested one, else what the device has.
QVariant wanted(const SystemSettings& settings, const SystemSettings& current, const QString& key) {
    return settings.contains(key) ? settings.value(key) : current.value(key);
}

void setField(Fields& fields, const QString& key, const char* field, const QVariant& value) {
    if (isTextKey(key)) {
        fields.setBytes(field, wireText(value.toString()));
    } else {
        fields.set(field, value.toLongLong());
    }
}

QString pageKeys(const SettingPage& page) {
    QStringList keys;
    for (const SettingField& field : page.fields) keys.append(QLatin1String(field.key));
    return keys.join(QLatin1String(", "));
}

}  // namespace

Result<SystemSettings> AsciiCamCon::readSettings(QStringList* skipped) {
    SystemSettings settings;
    for (const SettingPage& page : settingPages()) {
        const Result<Fields> reply = m_link.call('?', page.command);
        if (!reply) {
            if (isNotUnderstood(reply.error())) {
                if (skipped) {
                    skipped->append(QStringLiteral("?%1 (%2)")
                                        .arg(QLatin1String(page.command), pageKeys(page)));
                }
                continue;
            }
            return inContext(
                QCoreApplication::translate("cambench::comm", "reading the settings (?%1)")
                    .arg(QLatin1String(page.command)),
                reply.error());
        }
        for (const SettingField& field : page.fields) {
            const QString key = QLatin1String(field.key);
            settings.insert(key, isTextKey(key) ? QVariant(text(*reply, field.field))
                                                : QVariant(reply->num(field.field)));
        }
    }
    return settings;
}

Result<QVariant> AsciiCamCon::readSetting(const QString& key) {
    for (const SettingPage& page : settingPages()) {
        for (const SettingField& field : page.fields) {
            if (key != QLatin1String(field.key)) continue;
            const Result<Fields> reply = m_link.call('?', page.command);
            if (!reply) {
                return inContext(QCoreApplication::translate("cambench::comm", "reading %1 (?%2)")
                                     .arg(key, QLatin1String(page.command)),
                                 reply.error());
            }
            return isTextKey(key) ? QVariant(text(*reply, field.field))
                                  : QVariant(reply->num(field.field));
        }
    }
    return Error::usage(
        QCoreApplication::translate("cambench::comm", "\"%1\" is no device setting").arg(key));
}

Status AsciiCamCon::writeSettings(const SystemSettings& settings) {
    const Result<SystemSettings> current = readSettings();
    if (!current) return current.error();
    return writeSettings(settings, *current);
}

Status AsciiCamCon::writeSettings(const SystemSettings& settings, const SystemSettings& onDevice) {
    const SystemSettings* current = &onDevice;
    const QString text1 = QLatin1String(kEncoderText1Key);
    const QString text2 = QLatin1String(kEncoderText2Key);
    const bool textsChange =
        changes(settings, *current, text1) || changes(settings, *current, text2);
    const qint64 currentType = current->value(QLatin1String(kEncoderTypeKey), -1).toLongLong();

    for (const SettingPage& page : settingPages()) {
        if (!findCommand(kCommand, page.command)) continue;  // read-only page
        bool changed = page.encoderType >= 0 && textsChange && page.encoderType == currentType;
        for (const SettingField& field : page.fields) {
            changed = changed || changes(settings, *current, QLatin1String(field.key));
        }
        if (!changed) continue;
        Fields fields;
        for (const SettingField& field : page.fields) {
            const QString key = QLatin1String(field.key);
            setField(fields, key, field.field, wanted(settings, *current, key));
        }
        if (page.encoderType >= 0) {
            setField(fields, text1, "text1", wanted(settings, *current, text1));
            setField(fields, text2, "text2", wanted(settings, *current, text2));
            fields.set("type", page.encoderType);
        }
        const Result<Fields> reply = m_link.call('!', page.command, fields);
        if (!reply) {
            return inContext(QCoreApplication::translate("cambench::comm", "writing %1 (!%2)")
                                 .arg(pageKeys(page), QLatin1String(page.command)),
                             reply.error());
        }
    }
    return success();
}

}  // namespace cambench::comm
