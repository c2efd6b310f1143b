#include "system_settings.h"

#include <algorithm>
#include <limits>

// The one table of single-value settings (manual 5.3 and 5.4). The settings
// form, the project file and validation all follow from it; the command
// catalogue in comm/ maps the same keys to commands. Special-encoder pages
// whose manual pages are missing follow the provisional table of
// docs/protocols/camcon-ascii.md; their ranges are the field widths.

namespace cambench {

namespace {

constexpr qint64 kInt32Min = std::numeric_limits<qint32>::min();
constexpr qint64 kInt32Max = std::numeric_limits<qint32>::max();
// Outputs and inputs are addressed by 2 hex digits, 1..200 (0 = none).
constexpr qint64 kMaxIoNumber = 200;

SettingSpec integer(const char* key, const char* group, qint64 min, qint64 max, const char* unit,
                    const char* label, const char* tooltip, const char* section) {
    SettingSpec spec{};
    spec.key = key;
    spec.group = group;
    spec.kind = SettingKind::Integer;
    spec.min = min;
    spec.max = max;
    spec.unit = unit;
    spec.label = label;
    spec.tooltip = tooltip;
    spec.section = section;
    return spec;
}

SettingSpec choice(const char* key, const char* group, QList<SettingChoice> choices,
                   const char* label, const char* tooltip, const char* section) {
    SettingSpec spec = integer(key, group, 0, 0, "", label, tooltip, section);
    spec.kind = SettingKind::Enum;
    for (const SettingChoice& c : choices) {
        spec.min = std::min(spec.min, c.value);
        spec.max = std::max(spec.max, c.value);
    }
    spec.choices = std::move(choices);
    return spec;
}

SettingSpec ioRef(SettingKind kind, const char* key, const char* group, const char* label,
                  const char* tooltip, const char* section) {
    SettingSpec spec = integer(key, group, 0, kMaxIoNumber, "", label, tooltip, section);
    spec.kind = kind;
    return spec;
}

SettingSpec inputRef(const char* key, const char* group, const char* label, const char* tooltip,
                     const char* section) {
    return ioRef(SettingKind::InputRef, key, group, label, tooltip, section);
}

SettingSpec outputRef(const char* key, const char* group, const char* label, const char* tooltip,
                      const char* section) {
    return ioRef(SettingKind::OutputRef, key, group, label, tooltip, section);
}

SettingSpec text(const char* key, const char* group, int maxLength, const char* label,
                 const char* tooltip, const char* section) {
    SettingSpec spec = integer(key, group, 0, 0, "", label, tooltip, section);
    spec.kind = SettingKind::Text;
    spec.maxLength = maxLength;
    return spec;
}

SettingSpec fixed(const char* key, const char* group, qint64 min, qint64 max, int decimals,
                  const char* label, const char* tooltip, const char* section) {
    SettingSpec spec = integer(key, group, min, max, "", label, tooltip, section);
    spec.kind = SettingKind::Fixed;
    spec.decimals = decimals;
    return spec;
}

// A count that must be a multiple of 8 (manual 5.3.6, 5.4.6).
SettingSpec count8(const char* key, const char* group, qint64 min, qint64 max, const char* label,
                   const char* tooltip, const char* section) {
    SettingSpec spec = integer(key, group, min, max, "", label, tooltip, section);
    spec.step = 8;
    return spec;
}

SettingSpec readOnly(SettingSpec spec) {
    spec.readOnly = true;
    return spec;
}

const QList<SettingChoice> kOffOn = {{0, "Off"}, {1, "On"}};

QList<SettingSpec> buildSpecs() {
    QList<SettingSpec> specs;

    // 5.3.1 Encoder
    specs << choice("encoderType", "encoder",
                    {{0x00, "SSI 256 Gray singleturn"},
                     {0x01, "SSI 360 Gray singleturn"},
                     {0x02, "SSI 512 Gray singleturn"},
                     {0x03, "SSI 1000 Gray singleturn"},
                     {0x04, "SSI 1024 Gray singleturn"},
                     {0x05, "SSI 2048 Gray singleturn"},
                     {0x06, "SSI 4096 Gray singleturn"},
                     {0x07, "SSI 8192 Gray singleturn"},
                     {0x08, "Analogue SSI converter 8 bit (0..255)"},
                     {0x09, "Analogue SSI converter 12 bit (0..4095)"},
                     {0x0A, "SSI multiturn 4096 x 1 turn"},
                     {0x0B, "SSI multiturn 4096 x 2 turns"},
                     {0x0C, "SSI multiturn 4096 x 4 turns"},
                     {0x0D, "SSI multiturn 4096 x 8 turns"},
                     {0x0E, "SSI multiturn 4096 x 16 turns"},
                     {0x0F, "SSI multiturn 8192 x 2 turns"},
                     {0x10, "SSI multiturn 8192 x 4 turns"},
                     {0x11, "SSI multiturn 8192 x 8 turns"},
                     {0x12, "SSI multiturn 8192 x 16 turns"},
                     {0x13, "SSI multiturn 8192 x 32 turns"},
                     {0x14, "SSI multiturn 8192 x 64 turns"},
                     {0xFF, "Programmable special encoder"}},
                    "Encoder",
                    "The position encoder connected to the device, from the device's list of "
                    "encoders, or the programmable special encoder set up on the special "
                    "encoder page.",
                    "5.3.1.1");
    specs << readOnly(text("encoderText1", "encoder", 21, "Encoder text line 1",
                           "First text line describing the selected encoder, as the device "
                           "shows it.",
                           "5.3.1.3"));
    specs << readOnly(text("encoderText2", "encoder", 21, "Encoder text line 2",
                           "Second text line describing the selected encoder, as the device "
                           "shows it.",
                           "5.3.1.4"));
    specs << integer("actualValueHysteresis", "encoder", 0, 125, "increments",
                     "Actual value hysteresis",
                     "Change of the encoder value that is ignored, so that a shaft standing "
                     "on an edge does not make the outputs flicker.",
                     "5.3.1.5");
    specs << integer("maxIncrementsPerCycle", "encoder", 0, 9999, "increments",
                     "Maximum increments per cycle",
                     "Largest plausible change of the encoder value within one cycle; a "
                     "bigger jump is reported as an encoder error. 0 switches the check off.",
                     "5.3.1.7");
    SettingSpec multiplier =
        integer("gearMultiplier", "encoder", -99999, 99999, "", "Gear multiplier",
                "The encoder value is multiplied by this factor and divided "
                "by the gear divisor. A negative factor reverses the "
                "direction; 0 is not allowed.",
                "5.3.1.9");
    multiplier.excludeZero = true;
    specs << multiplier;
    specs << integer("gearDivisor", "encoder", 1, 99999, "", "Gear divisor",
                     "The encoder value multiplied by the gear multiplier is divided by this "
                     "number.",
                     "5.3.1.11");
    specs << text("actualValueFormat", "encoder", 9, "Actual value format",
                  "How the device displays the actual value (format text, e.g. the position of "
                  "the decimal point and the unit).",
                  "5.3.1.13");

    // 5.3.1.15 Programmable special encoder (provisional pages, notes 3)
    specs << readOnly(integer("specialEncoder.type", "specialEncoder", 0, 10, "",
                              "Special encoder type",
                              "Which kind of programmable special encoder is set up (5 = "
                              "timer). Chosen by writing one of the parameter pages.",
                              "5.3.1.15"));
    specs << text("specialEncoder.text1", "specialEncoder", 21, "Special encoder text line 1",
                  "First text line the device shows for the special encoder.", "5.3.1.15");
    specs << text("specialEncoder.text2", "specialEncoder", 21, "Special encoder text line 2",
                  "Second text line the device shows for the special encoder.", "5.3.1.15");
    specs << integer("specialEncoder.ssi.resolutionBits", "specialEncoder", 1, 32, "bits",
                     "SSI resolution", "Number of data bits the SSI encoder sends per value.",
                     "5.3.1.15");
    specs << integer("specialEncoder.ssi.firstBit", "specialEncoder", 0, 31, "", "SSI first bit",
                     "Position of the first valid bit in the SSI telegram.", "5.3.1.15");
    specs << integer("specialEncoder.ssi.capping", "specialEncoder", 0, 31, "bits", "SSI capping",
                     "Number of low bits cut off the SSI value.", "5.3.1.15");
    specs << integer("specialEncoder.ssi.errorBit", "specialEncoder", 0, 32, "", "SSI error bit",
                     "Bit of the SSI telegram that signals an encoder error (0 = none).",
                     "5.3.1.15");
    specs << integer("specialEncoder.parallel.resolution", "specialEncoder", 1, kInt32Max,
                     "increments", "Parallel encoder resolution",
                     "Increments per turn of the parallel encoder.", "5.3.1.15");
    specs << inputRef("specialEncoder.parallel.firstInput", "specialEncoder",
                      "Parallel encoder first input",
                      "First of the inputs the parallel encoder is wired to.", "5.3.1.15");
    specs << choice("specialEncoder.parallel.mode", "specialEncoder",
                    {{0, "Gray code"}, {1, "Binary"}}, "Parallel encoder code",
                    "Whether the parallel encoder sends Gray code or binary.", "5.3.1.15");
    specs << integer("specialEncoder.incremental.resolution", "specialEncoder", 1, kInt32Max,
                     "increments", "Incremental encoder resolution",
                     "Increments per turn of the incremental encoder.", "5.3.1.15");
    specs << integer("specialEncoder.incremental.divider", "specialEncoder", 1, kInt32Max, "",
                     "Incremental encoder divider",
                     "The incremental pulses are divided by this number.", "5.3.1.15");
    specs << integer("specialEncoder.incremental.clearMode", "specialEncoder", 0, 255, "",
                     "Incremental encoder clear mode",
                     "When the incremental counter is cleared (device-specific code).", "5.3.1.15");
    specs << integer("specialEncoder.multiturn.resolution", "specialEncoder", 1, kInt32Max,
                     "increments", "Multiturn resolution",
                     "Increments per turn of the multiturn encoder.", "5.3.1.15");
    specs << integer("specialEncoder.multiturn.turns", "specialEncoder", 1, kInt32Max, "turns",
                     "Multiturn turns", "Number of turns the multiturn encoder counts.",
                     "5.3.1.15");
    specs << integer("specialEncoder.multiturn.divider", "specialEncoder", 1, kInt32Max, "",
                     "Multiturn divider", "The multiturn value is divided by this number.",
                     "5.3.1.15");
    specs << integer("specialEncoder.pll.pulsesPerInputPulse", "specialEncoder", 1, kInt32Max, "",
                     "PLL pulses per input pulse",
                     "Increments the PLL generates for each input pulse.", "5.3.1.15");
    specs << integer("specialEncoder.pll.pulsesPerTurn", "specialEncoder", 1, kInt32Max, "",
                     "PLL pulses per turn", "Input pulses per turn of the machine.", "5.3.1.15");
    specs << integer("specialEncoder.pll.errorWindow", "specialEncoder", 0, kInt32Max, "increments",
                     "PLL error window",
                     "Deviation from the expected pulse count that is still accepted.", "5.3.1.15");
    specs << inputRef("specialEncoder.pll.pulseInput", "specialEncoder", "PLL pulse input",
                      "Input that receives the PLL's pulses.", "5.3.1.15");
    specs << inputRef("specialEncoder.pll.clearInput", "specialEncoder", "PLL clear input",
                      "Input that clears the PLL's position (0 = none).", "5.3.1.15");
    specs << outputRef("specialEncoder.pll.syncOutput", "specialEncoder", "PLL sync output",
                       "Output that signals that the PLL is synchronised (0 = none).", "5.3.1.15");
    specs << integer("specialEncoder.timer.stepMs", "specialEncoder", 0, kInt32Max, "ms",
                     "Timer step time", "Time after which the timer encoder counts one step.",
                     "5.3.1.15.12");
    specs << integer("specialEncoder.timer.resolution", "specialEncoder", 1, kInt32Max, "steps",
                     "Timer resolution",
                     "Steps of the timer encoder before it starts again at zero.", "5.3.1.15.12");
    specs << inputRef("specialEncoder.timer.holdInput", "specialEncoder", "Timer hold input",
                      "Input that holds the timer encoder (0 = none).", "5.3.1.15.12");
    specs << inputRef("specialEncoder.timer.clearInput", "specialEncoder", "Timer clear input",
                      "Input that sets the timer encoder back to zero (0 = none).", "5.3.1.15.12");

    // 5.3.2 Adaptation
    specs << choice("axisType", "adaptation", {{0, "Rotary"}, {1, "Linear"}}, "Axis type",
                    "Rotary: the actual value runs round and cams may wrap through zero. "
                    "Linear: the actual value runs from the start value upwards.",
                    "5.3.2.1");
    specs << integer("linearStartValue", "adaptation", kInt32Min, kInt32Max, "",
                     "Linear start value", "Actual value at the start of a linear axis.",
                     "5.3.2.3");
    specs << integer("offset", "adaptation", kInt32Min, kInt32Max, "", "Offset",
                     "Zero-point shift added to the encoder value.", "5.3.2.5");
    specs << integer("presetValue", "adaptation", kInt32Min, kInt32Max, "", "Preset value",
                     "Actual value the device takes when the preset input switches on.", "5.3.2.7");
    specs << inputRef("presetInput", "adaptation", "Preset input",
                      "Input that sets the actual value to the preset value (0 = none).",
                      "5.3.2.9");
    specs << choice("presetRetained", "adaptation", kOffOn, "Preset retained at power-off",
                    "Whether a preset survives switching the device off and on "
                    "(zero-voltage safe).",
                    "5.3.2.11");

    // 5.3.3 Speed
    specs << fixed("speedFactor", "speed", 1, 99999999, 5, "Speed factor",
                   "The measured speed is multiplied by this factor before it is displayed "
                   "(0.00001 to 999.99999).",
                   "5.3.3.1");
    specs << text("speedFormat", "speed", 9, "Speed format",
                  "How the device displays the speed (format text).", "5.3.3.3");
    specs << integer("speed100Percent", "speed", 1, 999999999, "", "100% speed value",
                     "Speed value that counts as 100 %, e.g. for the analogue speed output.",
                     "5.3.3.5");
    specs << fixed("speedAccuracy", "speed", 1, 999, 2, "Speed accuracy",
                   "Resolution of the speed measurement (0.01 to 9.99).", "5.3.3.7");
    specs << choice("displaySwitchMode", "speed", {{0, "Automatic"}, {1, "Speed"}, {2, "Position"}},
                    "Display mode",
                    "What the display shows: automatic change, speed or position. With speed "
                    "or position an input can switch the display.",
                    "5.3.3.9");
    specs << inputRef("displaySwitchInput", "speed", "Display switch input",
                      "Input that switches the display between speed and position (0 = none; "
                      "only in display mode Speed or Position).",
                      "5.3.3.11");

    // 5.3.4 Cable length / cycle
    specs << integer("cableLength", "cycle", 0, 1000, "m", "Cable length",
                     "Length of the encoder cable; the device compensates the signal delay.",
                     "5.3.4.1");
    specs << integer("targetCycleTime", "cycle", 0, 100000, "0.1 ms", "Minimum cycle time",
                     "Shortest time of one device cycle, in 0.1 ms steps (0 to 10000 ms).",
                     "5.3.4.3");
    specs << readOnly(integer("actualCycleTime", "cycle", 0, kInt32Max, "0.1 ms",
                              "Current cycle time",
                              "Time the device currently needs for one cycle, in 0.1 ms "
                              "steps.",
                              "5.3.4.5"));

    // 5.3.5 Special outputs
    specs << outputRef("safetyOutput", "specialOutputs", "Safety output",
                       "Output that is on while the device works without error (0 = none).",
                       "5.3.5.1");
    specs << choice("actualValueSendMode", "specialOutputs",
                    {{0, "Do not send"},
                     {1, "Send in Gray code"},
                     {2, "Send in binary"},
                     {3, "Send for DC115 master-slave"}},
                    "Actual value output",
                    "Whether and how the device passes its actual value on through outputs.",
                    "5.3.5.3");
    specs << outputRef("directionOutput", "specialOutputs", "Direction output",
                       "Output that shows the direction of rotation (0 = none).", "5.3.5.5");
    specs << outputRef("standstillOutput", "specialOutputs", "Standstill output",
                       "Output that switches when the axis stands still (0 = no standstill "
                       "detection).",
                       "5.3.5.7");
    specs << integer("speedHysteresis", "specialOutputs", 0, kInt32Max, "",
                     "Standstill speed hysteresis",
                     "Speed below which the axis counts as standing still.", "5.3.5.9");
    specs << choice("analogueSpeedOutput", "specialOutputs", kOffOn, "Analogue speed output",
                    "Whether the device puts out the speed as an analogue value.", "5.3.5.11");
    specs << integer("analogueCamOutputs", "specialOutputs", 0, 14, "", "Analogue cam outputs",
                     "Number of analogue cam outputs in use.", "5.3.5.13");

    // 5.3.6 System expansion
    specs << count8("inputCount", "expansion", 0, 200, "Inputs",
                    "Number of inputs the device has (multiples of 8).", "5.3.6.1");
    specs << count8("outputCount", "expansion", 8, 200, "Outputs",
                    "Number of outputs the device has (multiples of 8, 8 to 200).", "5.3.6.3");
    specs << count8("deadTimeOutputCount", "expansion", 0, 200, "Dead-time outputs",
                    "Number of outputs with dead-time compensation, counted from output 1 "
                    "(multiples of 8).",
                    "5.3.6.5");
    specs << inputRef("keyboardLockInput", "expansion", "Keyboard lock input",
                      "Input that locks the device's keyboard (0 = none).", "5.3.6.7");
    specs << integer("externalProgramInputs", "expansion", 0, 15, "",
                     "External program selection inputs",
                     "Number of inputs that select the program in binary (0 = no external "
                     "program selection).",
                     "5.3.6.9");
    specs << inputRef("externalProgramFirstInput", "expansion", "First program selection input",
                      "First of the inputs that select the program (0 = none).", "5.3.6.11");
    specs << choice("programSelection.mode", "expansion",
                    {{0, "Slow"}, {1, "Within one cycle"}, {2, "At actual value"}},
                    "Program selection mode",
                    "When a newly selected program takes effect: slowly, within one cycle, "
                    "or when the axis passes the program selection actual value.",
                    "5.3.6.13");
    specs << integer("programSelection.actualValue", "expansion", kInt32Min, kInt32Max, "",
                     "Program selection actual value",
                     "Actual value at which a new program takes effect (mode \"At actual "
                     "value\" only).",
                     "5.3.6.13");

    // 5.4.3 Device configuration
    specs << choice("protocol", "configuration",
                    {{0, "Cam-BUS"}, {1, "Standard"}, {2, "Multiuser"}, {3, "S5-L1"}, {4, "3964R"}},
                    "Communication protocol",
                    "Protocol of the serial interface. Changing it ends the connection with "
                    "the current protocol.",
                    "5.4.3.1");
    specs << integer("deviceNumber", "configuration", 0, 63, "", "Device number",
                     "Number of the device on a Multiuser or Cam-BUS line.", "5.4.3.3");
    specs << choice("analogueStatus", "configuration",
                    {{0, "No analogue value"},
                     {1, "1 internal analogue output"},
                     {2, "2 internal analogue outputs"}},
                    "Analogue outputs", "How many internal analogue outputs are in use.",
                    "5.4.3.6");
    specs << integer("analogue.offset1", "configuration", 0, 255, "", "Analogue 1 offset",
                     "Offset adjustment of analogue value 1.", "5.4.3.9");
    specs << integer("analogue.offset2", "configuration", 0, 255, "", "Analogue 2 offset",
                     "Offset adjustment of analogue value 2.", "5.4.3.11");
    specs << integer("analogue.factor1", "configuration", 0, 65535, "", "Analogue 1 factor",
                     "Gain adjustment of analogue value 1.", "5.4.3.13");
    specs << integer("analogue.factor2", "configuration", 0, 65535, "", "Analogue 2 factor",
                     "Gain adjustment of analogue value 2.", "5.4.3.15");
    specs << choice("terminalMode", "configuration", {{0, "Normal"}, {1, "Terminal"}},
                    "Terminal mode", "Normal operation or terminal operation of the device.",
                    "5.4.3.17");

    // 5.4.4 Language
    specs << integer("deviceLanguage", "language", 0, 255, "", "Device language",
                     "Language of the device's display: 0 German, 1 English, 2 French; "
                     "further numbers depend on the firmware.",
                     "5.4.4.1");

    // 5.4.6 PLC configuration
    specs << readOnly(choice("plcBooster", "configurationPlc", {{0, "Not fitted"}, {1, "Fitted"}},
                             "PLC accelerator", "Whether the PLC accelerator hardware is fitted.",
                             "5.4.6.1"));
    specs << choice("plcMode", "configurationPlc",
                    {{0, "Off"}, {1, "On"}, {2, "On, flags retained"}}, "PLC module",
                    "Switches the PLC module off or on; \"flags retained\" keeps the flags "
                    "at power-off.",
                    "5.4.6.2");
    specs << count8("plcInputs", "configurationPlc", 0, 200, "PLC inputs",
                    "Number of PLC inputs (multiples of 8).", "5.4.6.4");
    specs << count8("plcOutputs", "configurationPlc", 0, 200, "PLC outputs",
                    "Number of PLC outputs (multiples of 8).", "5.4.6.6");
    specs << count8("plcFlags", "configurationPlc", 0, 248, "PLC flags",
                    "Number of PLC flags (M, multiples of 8).", "5.4.6.8");
    specs << count8("plcXFlags", "configurationPlc", 0, 248, "PLC X flags",
                    "Number of PLC X flags (multiples of 8).", "5.4.6.10");
    specs << count8("plcTimersCounters", "configurationPlc", 0, 248, "PLC timers and counters",
                    "Number of PLC timers and counters (multiples of 8).", "5.4.6.12");
    specs << count8("plcVInputs", "configurationPlc", 0, 248, "PLC V inputs",
                    "Number of PLC V inputs (multiples of 8).", "5.4.6.14");
    specs << count8("plcSInputs", "configurationPlc", 0, 248, "PLC S inputs",
                    "Number of PLC S inputs (multiples of 8).", "5.4.6.16");
    return specs;
}

}  // namespace

const QList<SettingSpec>& settingSpecs() {
    static const QList<SettingSpec> specs = buildSpecs();
    return specs;
}

}  // namespace cambench
