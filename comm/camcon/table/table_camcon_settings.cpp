// System and encoder settings: area 203, a few words of 201 and 205
// (table_settings_map.h maps them to the model's keys).
#include "table_camcon.h"
#include "table_map.h"
#include "table_settings_map.h"
#include "table_word_block.h"

#include "comm/device/error_context.h"
#include "model/camcon/system_settings.h"

#include <QCoreApplication>
#include <QSet>

namespace cambench::comm::table {

namespace {

bool isWritable(const QString& key) {
    const SettingSpec* spec = findSetting(key);
    return spec && !spec->readOnly;
}

// Whether `settings` asks for a value of `key` other than the device's.
bool changes(const SystemSettings& settings, const SystemSettings& onDevice, const QString& key) {
    return settings.contains(key) && isWritable(key) &&
           (!onDevice.contains(key) ||
            settings.value(key).toLongLong() != onDevice.value(key).toLongLong());
}

// The value to write: the requested one, else what the device has.
qint64 wanted(const SystemSettings& settings, const SystemSettings& onDevice, const QString& key) {
    return (settings.contains(key) ? settings.value(key) : onDevice.value(key)).toLongLong();
}

// Writes each run of consecutive words of `words` (word -> value) in as few
// telegrams as it needs.
Status writeRuns(TableLink& link, int area, const QMap<int, qint32>& words) {
    auto it = words.begin();
    while (it != words.end()) {
        const int first = it.key();
        QList<qint32> run;
        while (it != words.end() && it.key() == first + run.size()) run.append(*it++);
        if (const Status written = link.writeWords(area, first, run); !written) return written;
    }
    return success();
}

// The settings as a person knows them: their labels (translated in the
// context "Settings", as on the settings page), not their JSON keys.
QString keyList(const QStringList& keys) {
    QStringList labels;
    for (const QString& key : keys) {
        const SettingSpec* spec = findSetting(key);
        labels << (spec && *spec->label ? QCoreApplication::translate("Settings", spec->label)
                                        : key);
    }
    return labels.join(QLatin1String(", "));
}

}  // namespace

Result<SystemSettings> TableCamCon::readSettings(QStringList* skipped) {
    const QString what =
        QCoreApplication::translate("cambench::comm", "reading the settings (data area %1)");
    const Result<WordBlock> system = WordBlock::read(m_link, kSystemArea, u"system.encoder_type",
                                                     u"system.standstill_hysteresis");
    if (!system) return inContext(what.arg(kSystemArea), system.error());
    const Result<WordBlock> config =
        WordBlock::read(m_link, kConfigArea, u"config.device_number", u"config.serial_mode");
    if (!config) return inContext(what.arg(kConfigArea), config.error());
    const Result<WordBlock> status =
        WordBlock::read(m_link, kStatusArea, u"status.plc_boost", u"status.cycle_time");
    if (!status) return inContext(what.arg(kStatusArea), status.error());
    const WordBlock* blocks[] = {&*system, &*config, &*status};

    SystemSettings settings;
    QStringList unshown;
    for (const TableSetting& setting : tableSettings()) {
        for (const WordBlock* block : blocks) {
            if (block->area() != setting.area) continue;
            const std::optional<qint64> value = settingFromWord(setting, block->word(setting.word));
            if (value) {
                settings.insert(QLatin1String(setting.key), *value);
            } else {
                unshown.append(QCoreApplication::translate("cambench::comm", "%1 (device value %2)")
                                   .arg(QLatin1String(setting.key))
                                   .arg(block->word(setting.word)));
            }
        }
    }
    const int type = system->at(u"system.special_encoder_type");
    for (int index = 0; index < kSpecialEncoderParameters; ++index) {
        if (const char* key = specialEncoderParameterKey(type, index))
            settings.insert(QLatin1String(key),
                            system->at(u"system.special_encoder_parameter", index));
    }
    if (skipped) {
        QStringList wordless;
        for (const SettingSpec& spec : settingSpecs()) {
            const QString key = QLatin1String(spec.key);
            if (!settings.contains(key) && !findTableSetting(key) &&
                !findSpecialEncoderParameter(key))
                wordless.append(key);
        }
        if (!wordless.isEmpty())
            skipped->append(QCoreApplication::translate("cambench::comm",
                                                        "%1 (no data word in the table interface)")
                                .arg(keyList(wordless)));
        if (!unshown.isEmpty())
            skipped->append(QCoreApplication::translate("cambench::comm",
                                                        "%1 (a value the settings cannot show)")
                                .arg(keyList(unshown)));
        skipped->append(QCoreApplication::translate(
                            "cambench::comm",
                            "the parameters of special encoder types other than the "
                            "selected type %1 (the device keeps only those of one type)")
                            .arg(type));
    }
    return settings;
}

Status TableCamCon::writeSettings(const SystemSettings& settings, const SystemSettings& onDevice) {
    QStringList unwritable;
    QMap<int, QMap<int, qint32>> words;  // area -> word -> value
    QSet<int> specialTypes;
    for (auto it = settings.begin(); it != settings.end(); ++it) {
        if (!changes(settings, onDevice, it.key())) continue;
        const TableSetting* setting = findTableSetting(it.key());
        const std::optional<SpecialEncoderParameter> special =
            findSpecialEncoderParameter(it.key());
        if (setting && setting->writable) {
            words[setting->area].insert(setting->word, settingToWord(*setting, it->toLongLong()));
        } else if (special) {
            specialTypes.insert(special->type);
        } else {
            unwritable.append(it.key());
        }
    }
    if (!unwritable.isEmpty()) {
        // Nothing is written: a partial write would pass for a complete one.
        return Error::invalidData(
            QCoreApplication::translate("cambench::comm",
                                        "%1 cannot be written over the table interface "
                                        "(no data word); leave them out. Nothing was "
                                        "written.")
                .arg(keyList(unwritable)));
    }
    // A special encoder is written as one block of words 0..7, which also
    // selects it (manual 3.4.1); several types: the last one stays selected.
    QList<int> types = specialTypes.values();
    std::sort(types.begin(), types.end());
    for (int type : std::as_const(types)) {
        QMap<int, qint32> block{{kSpecialEncoderFirstWord, kSpecialEncoderSelected},
                                {kSpecialEncoderFirstWord + 1, type}};
        for (int index = 0; index < kSpecialEncoderParameters; ++index) {
            const char* key = specialEncoderParameterKey(type, index);
            const qint64 value = key ? wanted(settings, onDevice, QLatin1String(key)) : 0;
            block.insert(tableWord(u"system.special_encoder_parameter", index), qint32(value));
        }
        words[kSystemArea].remove(kSpecialEncoderFirstWord);
        words[kSystemArea].remove(kSpecialEncoderFirstWord + 1);
        if (const Status written = writeRuns(m_link, kSystemArea, block); !written) {
            return inContext(QCoreApplication::translate("cambench::comm",
                                                         "writing the special encoder of type %1")
                                 .arg(type),
                             written.error());
        }
    }
    for (auto area = words.begin(); area != words.end(); ++area) {
        if (const Status written = writeRuns(m_link, area.key(), *area); !written) {
            return inContext(
                QCoreApplication::translate("cambench::comm", "writing the settings (data area %1)")
                    .arg(area.key()),
                written.error());
        }
    }
    return success();
}

Result<QVariant> TableCamCon::readSetting(const QString& key) {
    const QString what = QCoreApplication::translate("cambench::comm", "reading %1").arg(key);
    if (const TableSetting* setting = findTableSetting(key)) {
        const Result<qint32> word = m_link.readWord(setting->area, setting->word);
        if (!word) return inContext(what, word.error());
        const std::optional<qint64> value = settingFromWord(*setting, *word);
        if (!value) {
            return Error::invalidData(
                QCoreApplication::translate(
                    "cambench::comm", "%1: the device holds %2, which the settings cannot show")
                    .arg(what)
                    .arg(*word));
        }
        return QVariant(*value);
    }
    if (const std::optional<SpecialEncoderParameter> special = findSpecialEncoderParameter(key)) {
        const Result<WordBlock> block =
            WordBlock::read(m_link, kSystemArea, u"system.special_encoder_type",
                            u"system.special_encoder_parameter");
        if (!block) return inContext(what, block.error());
        const int type = block->at(u"system.special_encoder_type");
        if (type != special->type) {
            return Error::usage(
                QCoreApplication::translate("cambench::comm",
                                            "%1: the device's special encoder is of type %2, "
                                            "and it keeps the parameters of that type only")
                    .arg(what)
                    .arg(type));
        }
        return QVariant(qint64(block->at(u"system.special_encoder_parameter", special->index)));
    }
    return Error::usage(
        QCoreApplication::translate("cambench::comm",
                                    "\"%1\" is no setting the table interface has a data word for")
            .arg(key));
}

}  // namespace cambench::comm::table
