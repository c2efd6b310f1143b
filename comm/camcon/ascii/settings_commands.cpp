#include "settings_commands.h"

namespace cambench::comm {

const QList<SettingPage>& settingPages() {
    // One line per setting or page.
    // clang-format off
    static const QList<SettingPage> pages{
        // 5.3.1 Encoder
        {"GEBER", {{"encoderType", "value"}}},
        {"GTXT1", {{"encoderText1", "text"}, {kEncoderText1Key, "text"}}},
        {"GTXT2", {{"encoderText2", "text"}, {kEncoderText2Key, "text"}}},
        {"GISTHYS", {{"actualValueHysteresis", "value"}}},
        {"GVMAX", {{"maxIncrementsPerCycle", "value"}}},
        {"IMUL", {{"gearMultiplier", "value"}}},
        {"IDIV", {{"gearDivisor", "value"}}},
        {"IFOR", {{"actualValueFormat", "text"}}},
        // 5.3.2 Position adaptation
        {"WLIN", {{"axisType", "value"}}},
        {"WANF", {{"linearStartValue", "value"}}},
        {"WNULLV", {{"offset", "value"}}},
        {"WPRE", {{"presetValue", "value"}}},
        {"WEINPRE", {{"presetInput", "value"}}},
        {"WFLPRE", {{"presetRetained", "value"}}},
        // 5.3.3 Speed
        {"SFAK", {{"speedFactor", "value"}}},
        {"SFOR", {{"speedFormat", "text"}}},
        {"S100", {{"speed100Percent", "value"}}},
        {"SEXA", {{"speedAccuracy", "value"}}},
        {"SSPA", {{"displaySwitchMode", "value"}}},
        {"SSPE", {{"displaySwitchInput", "value"}}},
        // 5.3.4 Cable length / cycle
        {"GKL", {{"cableLength", "value"}}},
        {"GZYKLSOLL", {{"targetCycleTime", "value"}}},
        {"GZYKLIST", {{"actualCycleTime", "value"}}},
        // 5.3.5 Special outputs
        {"ASICH", {{"safetyOutput", "value"}}},
        {"GISTAUS", {{"actualValueSendMode", "value"}}},
        {"GVRAUS", {{"directionOutput", "value"}}},
        {"GV0AUS", {{"standstillOutput", "value"}}},
        {"GV0SPEED", {{"speedHysteresis", "value"}}},
        {"ASPEED", {{"analogueSpeedOutput", "value"}}},
        {"ANOCK", {{"analogueCamOutputs", "value"}}},
        // 5.3.6 System layout
        {"EMAX", {{"inputCount", "value"}}},
        {"AMAX", {{"outputCount", "value"}}},
        {"GTZKANZ", {{"deadTimeOutputCount", "value"}}},
        {"GTLOCK", {{"keyboardLockInput", "value"}}},
        {"GPRGEXT", {{"externalProgramInputs", "value"}}},
        {"GPRGEINEXT", {{"externalProgramFirstInput", "value"}}},
        {"GPATYP", {{"programSelection.mode", "mode"}, {"programSelection.actualValue", "value"}}},
        // 5.4.3 Device configuration
        {"GSIO", {{"protocol", "value"}}},
        {"GNR", {{"deviceNumber", "value"}}},
        {"GANL", {{"analogueStatus", "value"}}},
        {"A1", {{"analogue.offset1", "value"}}},
        {"A2", {{"analogue.offset2", "value"}}},
        {"A3", {{"analogue.factor1", "value"}}},
        {"A4", {{"analogue.factor2", "value"}}},
        {"GTERM", {{"terminalMode", "value"}}},
        // 5.4.4 Language
        {"GSPRACHE", {{"deviceLanguage", "value"}}},
        // 5.4.6 PLC configuration
        {"GBOOST", {{"plcBooster", "value"}}},
        {"GONSPS", {{"plcMode", "value"}}},
        {"GESPSMAX", {{"plcInputs", "value"}}},
        {"GASPSMAX", {{"plcOutputs", "value"}}},
        {"GMSPSMAX", {{"plcFlags", "value"}}},
        {"GXSPSMAX", {{"plcXFlags", "value"}}},
        {"GTSPSMAX", {{"plcTimersCounters", "value"}}},
        {"GVSPSMAX", {{"plcVInputs", "value"}}},
        {"GSSPSMAX", {{"plcSInputs", "value"}}},
        // 5.3.1.15 Programmable special encoder. The page types other than
        // the timer's 5 (manual 5.3.1.15.13) are provisional guesses.
        {"GSTYP", {{kEncoderTypeKey, "value"}}},
        {"GSSSI", {{"specialEncoder.ssi.resolutionBits", "resolutionBits"}, {"specialEncoder.ssi.firstBit", "firstBit"}, {"specialEncoder.ssi.capping", "capping"}, {"specialEncoder.ssi.errorBit", "errorBit"}}, 0},
        {"GSPAR", {{"specialEncoder.parallel.resolution", "resolution"}, {"specialEncoder.parallel.firstInput", "firstInput"}, {"specialEncoder.parallel.mode", "mode"}}, 1},
        {"GSINK", {{"specialEncoder.incremental.resolution", "resolution"}, {"specialEncoder.incremental.divider", "divider"}, {"specialEncoder.incremental.clearMode", "clearMode"}}, 2},
        {"GSMULTI", {{"specialEncoder.multiturn.resolution", "resolution"}, {"specialEncoder.multiturn.turns", "turns"}, {"specialEncoder.multiturn.divider", "divider"}}, 3},
        {"GSPLL", {{"specialEncoder.pll.pulsesPerInputPulse", "pulsesPerInputPulse"}, {"specialEncoder.pll.pulsesPerTurn", "pulsesPerTurn"}, {"specialEncoder.pll.errorWindow", "errorWindow"}, {"specialEncoder.pll.pulseInput", "pulseInput"}, {"specialEncoder.pll.clearInput", "clearInput"}, {"specialEncoder.pll.syncOutput", "syncOutput"}}, 4},
        {"GSTIM", {{"specialEncoder.timer.stepMs", "stepTime"}, {"specialEncoder.timer.resolution", "resolution"}, {"specialEncoder.timer.holdInput", "holdInput"}, {"specialEncoder.timer.clearInput", "clearInput"}}, 5},
    };
    // clang-format on
    return pages;
}

}  // namespace cambench::comm
