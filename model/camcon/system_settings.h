#pragma once

#include <QList>
#include <QMap>
#include <QString>
#include <QStringList>
#include <QVariant>

namespace cambench {

// How a setting is shown and checked. Drives the settings form, the JSON
// file and validation from one table (cf. QGroundControl's Fact metadata).
enum class SettingKind {
    Integer,    // plain number in [min,max], optionally a multiple of `step`
    Enum,       // one of `choices` (value -> label)
    OutputRef,  // output number 1..200, 0 = none
    InputRef,   // input number 1..200, 0 = none
    Text,       // up to `maxLength` characters
    Fixed,      // decimal with `decimals` places, stored as the scaled integer
};

struct SettingChoice {
    qint64 value;
    const char* label;  // English; translated in ui/ (context "Settings")
};

struct SettingSpec {
    const char* key;    // stable JSON key, e.g. "actualValueHysteresis"
    const char* group;  // "encoder", "adaptation", "speed", "cycle",
                        // "specialOutputs", "configuration", "configurationPlc", ...
    SettingKind kind;
    qint64 min = 0;
    qint64 max = 0;
    int step = 1;       // value must be a multiple of step (counts of 8)
    int decimals = 0;   // Fixed only
    int maxLength = 0;  // Text only (visible characters)
    const char* unit = "";
    const char* label = "";
    const char* tooltip = "";  // what it does, from the manual
    const char* section = "";  // manual section
    QList<SettingChoice> choices{};
    bool readOnly = false;
    bool excludeZero = false;  // [min,max] without 0 (gear multiplier)
};

// Every setting of manual 5.3 and 5.4 that is a single value.
const QList<SettingSpec>& settingSpecs();
const SettingSpec* findSetting(const QString& key);

// Values by key: qint64 for numbers (Fixed: the scaled integer), QString for
// texts. Composite pages (special encoder, analogue channels, program
// selection mode) use dotted keys, e.g. "specialEncoder.ssi.resolutionBits".
using SystemSettings = QMap<QString, QVariant>;

// Empty when valid; otherwise one message per offending key, naming it.
QStringList validateSettings(const SystemSettings& settings);

// Empty when `value` fits `spec`; otherwise why not and what is allowed,
// without the key ("0 is not allowed; allowed are -99999..-1 and 1..99999").
// Numbers must be integer QVariants (Fixed: the scaled integer), texts
// QStrings.
QString settingValueProblem(const SettingSpec& spec, const QVariant& value);

// A Fixed or Integer value as a person writes it ("0.00001" for a speed
// factor of 1 with 5 decimals).
QString formatSettingValue(const SettingSpec& spec, qint64 value);

// "axisType" (?WLIN): 0 rotary, 1 linear. A project without it is rotary,
// as the default range 0..359 suggests.
bool isRotaryAxis(const SystemSettings& settings);

}  // namespace cambench
