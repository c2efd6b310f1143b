#include "table_settings_map.h"

#include "table_map.h"

#include <QString>

namespace cambench::comm::table {

namespace {

// Area 203 word 0: -1 = the special encoder on the first SSI interface; the
// model's encoder list writes it 0xFF. Values for a second interface
// (DC190: 0xBFFFFFFF, bit 30) have no place in the model.
constexpr qint64 kModelSpecialEncoder = 0xFF;
constexpr qint64 kLastListedEncoder = 0x14;

std::optional<qint64> encoderFromWord(qint32 word) {
    if (word == kSpecialEncoderSelected) return kModelSpecialEncoder;
    if (word >= 0 && word <= kLastListedEncoder) return word;
    return std::nullopt;
}
qint32 encoderToWord(qint64 value) {
    return value == kModelSpecialEncoder ? kSpecialEncoderSelected : qint32(value);
}

// Cycle times: µs in the table, 0.1 ms in the model (?GZYKLSOLL).
constexpr qint64 kMicrosecondsPerTenth = 100;
std::optional<qint64> cycleFromWord(qint32 word) {
    return word / kMicrosecondsPerTenth;
}
qint32 cycleToWord(qint64 value) {
    return qint32(value * kMicrosecondsPerTenth);
}

// Area 205 word 11: 4 = 3964R n96, 5 = 3964R e38; the model (?GSIO) has
// one "3964R", 4.
constexpr qint32 kSerialMode3964rN96 = 4;
constexpr qint32 kSerialMode3964rE38 = 5;
std::optional<qint64> serialModeFromWord(qint32 word) {
    return word == kSerialMode3964rE38 ? kSerialMode3964rN96 : word;
}

// clang-format off
const TableSetting kSettings[] = {
    // 3.4 Area 203 (writing restarts the device)
    {"encoderType",                 203,  0, true, encoderFromWord, encoderToWord},
    {kSpecialEncoderTypeKey,        203,  1, true, nullptr, nullptr},
    {"actualValueHysteresis",       203,  8, true, nullptr, nullptr},
    {"maxIncrementsPerCycle",       203,  9, true, nullptr, nullptr},
    {"gearMultiplier",              203, 10, true, nullptr, nullptr},
    {"gearDivisor",                 203, 11, true, nullptr, nullptr},
    {"axisType",                    203, 12, true, nullptr, nullptr},
    {"linearStartValue",            203, 13, true, nullptr, nullptr},
    {"offset",                      203, 14, true, nullptr, nullptr},
    {"presetValue",                 203, 15, true, nullptr, nullptr},
    {"presetInput",                 203, 16, true, nullptr, nullptr},
    {"presetRetained",              203, 17, true, nullptr, nullptr},
    {"speedFactor",                 203, 18, true, nullptr, nullptr},
    {"speed100Percent",             203, 19, true, nullptr, nullptr},
    {"speedAccuracy",               203, 20, true, nullptr, nullptr},
    {"displaySwitchMode",           203, 21, true, nullptr, nullptr},
    {"displaySwitchInput",          203, 22, true, nullptr, nullptr},
    {"cableLength",                 203, 23, true, nullptr, nullptr},
    {"targetCycleTime",             203, 24, true, cycleFromWord, cycleToWord},
    {"safetyOutput",                203, 25, true, nullptr, nullptr},
    {"actualValueSendMode",         203, 26, true, nullptr, nullptr},
    {"directionOutput",             203, 27, true, nullptr, nullptr},
    {"standstillOutput",            203, 28, true, nullptr, nullptr},
    {"speedHysteresis",             203, 29, true, nullptr, nullptr},
    {"plcInputs",                   203, 30, true, nullptr, nullptr},
    {"plcOutputs",                  203, 31, true, nullptr, nullptr},
    {"deadTimeOutputCount",         203, 32, true, nullptr, nullptr},
    {"keyboardLockInput",           203, 33, true, nullptr, nullptr},
    {"externalProgramInputs",       203, 34, true, nullptr, nullptr},
    {"externalProgramFirstInput",   203, 35, true, nullptr, nullptr},
    {"programSelection.mode",       203, 36, true, nullptr, nullptr},
    {"programSelection.actualValue", 203, 37, true, nullptr, nullptr},
    {"analogueCamOutputs",          203, 38, true, nullptr, nullptr},
    {"analogueSpeedOutput",         203, 39, true, nullptr, nullptr},
    {"analogueStatus",              203, 40, true, nullptr, nullptr},
    {"analogue.offset1",            203, 41, true, nullptr, nullptr},
    {"analogue.offset2",            203, 42, true, nullptr, nullptr},
    {"analogue.factor1",            203, 43, true, nullptr, nullptr},
    {"analogue.factor2",            203, 44, true, nullptr, nullptr},
    {"plcMode",                     203, 45, true, nullptr, nullptr},
    {"inputCount",                  203, 46, true, nullptr, nullptr},
    {"outputCount",                 203, 47, true, nullptr, nullptr},
    {"plcFlags",                    203, 48, true, nullptr, nullptr},
    {"plcXFlags",                   203, 49, true, nullptr, nullptr},
    {"plcTimersCounters",           203, 50, true, nullptr, nullptr},
    {"plcVInputs",                  203, 51, true, nullptr, nullptr},
    {"plcSInputs",                  203, 52, true, nullptr, nullptr},
    // 3.2 Area 201 (read-only values)
    {"plcBooster",                  201, 17, false, nullptr, nullptr},
    {"actualCycleTime",             201, 37, false, cycleFromWord, nullptr},
    // 3.6 Area 205
    {"deviceNumber",                205,  0, true, nullptr, nullptr},
    {"protocol",                    205, 11, true, serialModeFromWord, nullptr},
};

// Special encoder parameters (words 2..7) that the model names, by type
// (manual 3.4.1.1 - 3.4.1.6; table_map.cpp lists every type's words).
struct SpecialKey {
    int type;
    int index;
    const char* key;
};
const SpecialKey kSpecialKeys[] = {
    {0, 0, "specialEncoder.ssi.resolutionBits"},
    {0, 1, "specialEncoder.ssi.firstBit"},
    {0, 2, "specialEncoder.ssi.capping"},
    {0, 3, "specialEncoder.ssi.errorBit"},
    {1, 0, "specialEncoder.parallel.resolution"},
    {1, 1, "specialEncoder.parallel.firstInput"},
    {1, 2, "specialEncoder.parallel.mode"},
    {2, 0, "specialEncoder.incremental.resolution"},
    {2, 1, "specialEncoder.incremental.divider"},
    {2, 2, "specialEncoder.incremental.clearMode"},
    {3, 0, "specialEncoder.multiturn.resolution"},
    {3, 1, "specialEncoder.multiturn.turns"},
    {3, 2, "specialEncoder.multiturn.divider"},
    {4, 0, "specialEncoder.pll.pulsesPerInputPulse"},
    {4, 1, "specialEncoder.pll.pulsesPerTurn"},
    {4, 2, "specialEncoder.pll.errorWindow"},
    {4, 3, "specialEncoder.pll.pulseInput"},
    {4, 4, "specialEncoder.pll.clearInput"},
    {4, 5, "specialEncoder.pll.syncOutput"},
    {5, 0, "specialEncoder.timer.resolution"},
    {5, 1, "specialEncoder.timer.stepMs"},
    {5, 2, "specialEncoder.timer.holdInput"},
    {5, 3, "specialEncoder.timer.clearInput"},
};
// clang-format on

}  // namespace

const QList<TableSetting>& tableSettings() {
    static const QList<TableSetting> settings(std::begin(kSettings), std::end(kSettings));
    return settings;
}

const TableSetting* findTableSetting(QStringView key) {
    for (const TableSetting& setting : tableSettings()) {
        if (key == QLatin1String(setting.key)) return &setting;
    }
    return nullptr;
}

std::optional<qint64> settingFromWord(const TableSetting& setting, qint32 word) {
    return setting.fromWord ? setting.fromWord(word) : std::optional<qint64>(word);
}

qint32 settingToWord(const TableSetting& setting, qint64 value) {
    return setting.toWord ? setting.toWord(value) : qint32(value);
}

const char* specialEncoderParameterKey(int type, int index) {
    for (const SpecialKey& special : kSpecialKeys) {
        if (special.type == type && special.index == index) return special.key;
    }
    return nullptr;
}

std::optional<SpecialEncoderParameter> findSpecialEncoderParameter(QStringView key) {
    for (const SpecialKey& special : kSpecialKeys) {
        if (key == QLatin1String(special.key))
            return SpecialEncoderParameter{special.type, special.index};
    }
    return std::nullopt;
}

}  // namespace cambench::comm::table
