// Areas 203 (system and encoder settings), 204 (analogue outputs) and 205
// (device configuration), manual 3.4 - 3.6. A setting the model knows is
// read and written through the device's ASCII handler of its command, so
// that both protocols see and check the same value; the others are words
// of SimTableState.
#include "sim_table_areas.h"

#include "comm/camcon/ascii/settings_commands.h"
#include "comm/camcon/table/table_map.h"
#include "comm/camcon/table/table_settings_map.h"
#include "comm/sim/camcon/sim_device.h"

namespace cambench::comm::sim_table {

using table::Rk512Error;

namespace {

// The command and field that hold model key `key`.
struct PageField {
    const SettingPage* page = nullptr;
    const char* field = nullptr;
};
PageField pageOf(const char* key) {
    for (const SettingPage& page : settingPages()) {
        for (const SettingField& field : page.fields) {
            if (qstrcmp(field.key, key) == 0) return {&page, field.field};
        }
    }
    return {};
}

const SettingPage* specialPage(qint64 type) {
    for (const SettingPage& page : settingPages()) {
        if (page.encoderType >= 0 && page.encoderType == type) return &page;
    }
    return nullptr;
}

Fields fieldsOf(SimDevice& device, const char* command) {
    const std::optional<SimResult> result = device.call(kQuery, command);
    return result && result->kind == SimResult::Data ? result->fields : Fields();
}

SimAreaReply refused(const QString& what) {
    return SimAreaReply::fail(Rk512Error::General, QStringLiteral("%1 refused").arg(what));
}

// Runs the '!' handler of `command` with `fields`.
SimAreaReply command(SimDevice& device, const char* name, const Fields& fields) {
    const std::optional<SimResult> result = device.call(kCommand, name, fields);
    if (!result || result->kind == SimResult::Error) return refused(QLatin1String(name));
    return {};
}

// Writes the special-encoder page of `type`, with `field` set to `value`
// when given: as !GSSSI etc. do, this also selects the special encoder.
SimAreaReply writeSpecialPage(SimDevice& device, qint64 type, const char* field = nullptr,
                              qint64 value = 0) {
    const SettingPage* page = specialPage(type);
    if (!page) return refused(QStringLiteral("special encoder type %1").arg(type));
    Fields fields = fieldsOf(device, page->command);
    if (field) fields.set(field, value);
    fields.setBytes("text1", fieldsOf(device, "GTXT1").bytes("text"));
    fields.setBytes("text2", fieldsOf(device, "GTXT2").bytes("text"));
    fields.set("type", type);
    return command(device, page->command, fields);
}

qint32 readSystemWord(SimDevice& device, int word) {
    const int firstParameter = table::tableWord(u"system.special_encoder_parameter");
    if (word >= firstParameter && word < firstParameter + table::kSpecialEncoderParameters) {
        const qint64 type = fieldsOf(device, "GSTYP").num("value");
        const char* key = table::specialEncoderParameterKey(int(type), word - firstParameter);
        const PageField where = key ? pageOf(key) : PageField{};
        if (!where.page) return device.tableState().words.value({table::kSystemArea, word});
        return qint32(fieldsOf(device, where.page->command).num(where.field));
    }
    for (const table::TableSetting& setting : table::tableSettings()) {
        if (setting.area != table::kSystemArea || setting.word != word) continue;
        const PageField where = pageOf(setting.key);
        if (!where.page) break;
        return table::settingToWord(setting,
                                    fieldsOf(device, where.page->command).num(where.field));
    }
    return device.tableState().words.value({table::kSystemArea, word});
}

SimAreaReply writeSystemWord(SimDevice& device, int word, qint32 value) {
    const int firstParameter = table::tableWord(u"system.special_encoder_parameter");
    if (word == table::tableWord(u"system.special_encoder_type"))
        return writeSpecialPage(device, value);
    if (word >= firstParameter && word < firstParameter + table::kSpecialEncoderParameters) {
        const qint64 type = fieldsOf(device, "GSTYP").num("value");
        const char* key = table::specialEncoderParameterKey(int(type), word - firstParameter);
        const PageField where = key ? pageOf(key) : PageField{};
        if (!where.page) {
            device.tableState().words.insert({table::kSystemArea, word}, value);
            return {};
        }
        return writeSpecialPage(device, type, where.field, value);
    }
    for (const table::TableSetting& setting : table::tableSettings()) {
        if (setting.area != table::kSystemArea || setting.word != word) continue;
        const PageField where = pageOf(setting.key);
        if (!where.page) break;
        const std::optional<qint64> modelValue = table::settingFromWord(setting, value);
        if (!modelValue) return refused(QStringLiteral("%1 = %2").arg(setting.key).arg(value));
        Fields fields = fieldsOf(device, where.page->command);
        fields.set(where.field, *modelValue);
        return command(device, where.page->command, fields);
    }
    device.tableState().words.insert({table::kSystemArea, word}, value);
    return {};
}

SimAreaReply writeConfigWord(SimDevice& device, int word, qint32 value) {
    const QString key = QLatin1String(table::locateTableWord(table::kConfigArea, word)->entry->key);
    if (key == QLatin1String("config.device_number"))
        return command(device, "GNR", Fields().set("value", value));
    if (key == QLatin1String("config.clear_all")) {
        const qint32 serialMode = device.tableState().words.value({table::kConfigArea, word});
        device.clearAll();
        device.tableState().words.insert({table::kConfigArea, word}, serialMode);
        return {};
    }
    if (key == QLatin1String("config.hardware_reset")) {
        SimAreaReply reply;
        reply.silent = true;  // the manual: this write is not acknowledged
        return reply;
    }
    if (key == QLatin1String("config.error_ack")) {
        device.runtime().errorState = 0;
        return {};
    }
    if (key == QLatin1String("config.eeprom_lock")) {
        if (value != 0 && value != 1) return refused(QStringLiteral("EEPROM lock %1").arg(value));
        device.tableState().eepromLocked = value == 1;
        return {};
    }
    device.tableState().words.insert({table::kConfigArea, word}, value);
    return {};
}

}  // namespace

WordRead readSettingWord(SimDevice& device, int area, int word) {
    if (area == table::kSystemArea) return {readSystemWord(device, word), Rk512Error::None, {}};
    if (area == table::kConfigArea) {
        if (word == table::tableWord(u"config.device_number"))
            return {qint32(fieldsOf(device, "GNR").num("value")), Rk512Error::None, {}};
        if (word == table::tableWord(u"config.eeprom_lock"))
            return {device.tableState().eepromLocked ? 1 : 0, Rk512Error::None, {}};
    }
    return {device.tableState().words.value({area, word}), Rk512Error::None, {}};
}

SimAreaReply writeSettingWord(SimDevice& device, int area, int word, qint32 value) {
    const std::optional<table::TableLocation> location = table::locateTableWord(area, word);
    if (area != table::kAnalogOutputArea &&
        (!location || !table::canWrite(location->entry->access))) {
        return SimAreaReply::fail(
            Rk512Error::General,
            QStringLiteral("word %1 of area %2 is read-only").arg(word).arg(area));
    }
    if (area == table::kSystemArea) return writeSystemWord(device, word, value);
    if (area == table::kConfigArea) return writeConfigWord(device, word, value);
    device.tableState().words.insert({area, word}, value);
    return {};
}

}  // namespace cambench::comm::sim_table
