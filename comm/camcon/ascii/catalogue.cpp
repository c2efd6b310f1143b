#include "catalogue.h"

#include "frame.h"

namespace cambench::comm {

namespace {

// Normalised widths (notes 2).
constexpr int kSmall = 2;         // small numbers, flags, input/output numbers, counts
constexpr int kProgram = 4;       // program numbers, ?GPRGMAX, ?GVMAX
constexpr int kWord = 4;          // 16-bit words
constexpr int kLong = 8;          // every field the manual writes with 7 or 8 letters
constexpr int kTextLine = 22;     // names and text lines, including the NUL
constexpr int kFormat = 10;       // display formats and formatted values, including the NUL
constexpr int kUserNumber = 6;    // user numbers, including the NUL
constexpr int kEpromDate = 11;    // "tt.tt.tttt" + NUL
constexpr int kAccessBytes = 32;  // 256 output access bits of ?USER/!USER
constexpr int kPlcSymbols = 30;   // 5 current paths x 6 symbols (notes 5)

FieldSpec hex(const char* name, int width) {
    return {name, FieldType::Hex, width};
}
FieldSpec signedHex(const char* name, int width = kLong) {
    return {name, FieldType::SignedHex, width};
}
FieldSpec text(const char* name, int width) {
    return {name, FieldType::Text, width};
}
FieldSpec textRest(const char* name) {
    return {name, FieldType::TextRest, -1};
}
FieldSpec binary(const char* name, int bytes) {
    return {name, FieldType::Binary, bytes};
}
FieldSpec hexBytes(const char* name) {
    return {name, FieldType::HexBytes, -1};
}
FieldSpec hexWords(const char* name, int width, int count) {
    return {name, FieldType::HexWords, width, count};
}

// Query with a data reply; command acknowledged with "OK".
CommandSpec query(const char* name, QList<FieldSpec> request, QList<FieldSpec> reply,
                  const char* section) {
    return {kQuery, name, std::move(request), ReplyKind::Data, std::move(reply), section};
}
CommandSpec command(const char* name, QList<FieldSpec> request, const char* section) {
    return {kCommand, name, std::move(request), ReplyKind::Ok, {}, section};
}

// The provisional readings, one id each (comm/camcon/README.md lists them
// with what they guess): what `check` names when a device refutes one.
constexpr const char* kPStatusName =
    "provisional: P-ASCII-1, our reading, see comm/camcon/README.md";
constexpr const char* kPSpeed = "provisional: P-ASCII-2, our reading, see comm/camcon/README.md";
constexpr const char* kPActual = "provisional: P-ASCII-3, our reading, see comm/camcon/README.md";
constexpr const char* kPProgram = "provisional: P-ASCII-4, our reading, see comm/camcon/README.md";
constexpr const char* kPNc = "provisional: P-ASCII-5, our reading, see comm/camcon/README.md";
constexpr const char* kPDeadTime = "provisional: P-ASCII-6, our reading, see comm/camcon/README.md";
constexpr const char* kPOutputName =
    "provisional: P-ASCII-7, our reading, see comm/camcon/README.md";
constexpr const char* kPEncoder = "provisional: P-ASCII-8, our reading, see comm/camcon/README.md";
constexpr const char* kPMemoryName =
    "provisional: P-ASCII-9, our reading, see comm/camcon/README.md";

CommandSpec provisional(CommandSpec spec, const char* source) {
    spec.provisional = source;
    return spec;
}
CommandSpec slow(CommandSpec spec) {
    spec.timeout = TimeoutClass::Long;
    return spec;
}
// Executing it twice changes the device (a cursor step, an insert, a
// delete): a retry is allowed, but the caller checks the device after one.
CommandSpec actsTwice(CommandSpec spec) {
    spec.retry = RetryPolicy::CheckAfter;
    return spec;
}
// Executing it twice breaks a sequence nobody can check from the reply: the
// EEPROM transfer answers a repeated block with -43 (its caller resends).
CommandSpec sendOnce(CommandSpec spec) {
    spec.retry = RetryPolicy::Never;
    return spec;
}
CommandSpec withOkOptional(CommandSpec spec) {
    spec.okOptional = true;
    return spec;
}
CommandSpec withReplyAlias(CommandSpec spec, const char* alias) {
    spec.replyAliases.append(QByteArray(alias));
    return spec;
}
CommandSpec withoutReply(CommandSpec spec) {
    spec.replyKind = ReplyKind::None;
    return spec;
}

// Single-value settings read and write a field named "value" (numbers) or
// "text" (texts), so that settings code can treat them generically.
QList<FieldSpec> value(int width) {
    return {hex("value", width)};
}
QList<FieldSpec> signedValue() {
    return {signedHex("value")};
}
QList<FieldSpec> textValue(int width) {
    return {text("text", width)};
}

// Special encoder blocks (notes 3, provisional): '!' = the two text lines and
// the type, then the same fields as the '?' reply.
QList<FieldSpec> encoderWrite(const QList<FieldSpec>& fields) {
    return QList<FieldSpec>{text("text1", kTextLine), text("text2", kTextLine),
                            hex("type", kSmall)} +
           fields;
}

QList<CommandSpec> buildCatalogue() {
    // Field lists shared by several rows. Locals, not globals: the catalogue
    // may be built during another file's static initialisation.
    const QList<FieldSpec> kNone{};
    const QList<FieldSpec> kStatusTable{hexBytes("data")};
    // The cam a search found (notes 3) and the flags "earlier" and "more".
    const QList<FieldSpec> kCamBoth{signedHex("on"), signedHex("off"), hex("earlier", kSmall),
                                    hex("more", kSmall)};
    const QList<FieldSpec> kSsi{hex("resolutionBits", kLong), hex("firstBit", kLong),
                                hex("capping", kLong), hex("errorBit", kLong)};
    const QList<FieldSpec> kParallel{hex("resolution", kLong), hex("firstInput", kSmall),
                                     hex("mode", kSmall)};
    const QList<FieldSpec> kIncremental{hex("resolution", kLong), hex("divider", kLong),
                                        hex("clearMode", kSmall)};
    const QList<FieldSpec> kMultiturn{hex("resolution", kLong), hex("turns", kLong),
                                      hex("divider", kLong)};
    const QList<FieldSpec> kPll{hex("pulsesPerInputPulse", kLong), hex("pulsesPerTurn", kLong),
                                hex("errorWindow", kLong),         hex("pulseInput", kSmall),
                                hex("clearInput", kSmall),         hex("syncOutput", kSmall)};
    const QList<FieldSpec> kTimer{hex("stepTime", kLong), hex("resolution", kLong),
                                  hex("holdInput", kSmall), hex("clearInput", kSmall)};
    const QList<FieldSpec> kAnalogueMode{signedHex("minimum"),        signedHex("maximum"),
                                         text("format", kFormat),     hex("interpolation", kSmall),
                                         hex("disableInput", kSmall), signedHex("disableValue"),
                                         signedHex("gain"),           signedHex("offset", kWord)};
    const QList<FieldSpec> kUserFields{text("name", kTextLine), text("number", kUserNumber),
                                       binary("access", kAccessBytes), hex("all", kSmall),
                                       hex("rights", kLong)};
    const QList<FieldSpec> kPlcAddress{hex("area", kSmall), hex("number", kSmall)};
    const QList<FieldSpec> kPlcNetwork{hex("area", kSmall), hex("number", kSmall),
                                       signedHex("value"), hex("reset", kWord),
                                       hexWords("symbols", kWord, kPlcSymbols)};
    const QList<FieldSpec> kPlcValue{hex("area", kSmall), hex("number", kSmall),
                                     signedHex("value")};
    const QList<FieldSpec> kErrorText{hex("message", kSmall), text("text1", kTextLine),
                                      text("text2", kTextLine), text("text3", kTextLine),
                                      text("text4", kTextLine)};

    return {
        // 4.3 Checksum on/off (the !C0 request itself carries no checksum).
        command("C0", kNone, "4.3.1"),
        command("C1", kNone, "4.3.2"),

        // 5.1 Display menu
        query("ERR", kNone, value(kSmall), "5.1.1"),
        command("ERR", kNone, "5.1.2"),
        query("AUTO", kNone, {textRest("text")}, "5.1.3"),
        query("ATAB", kNone, kStatusTable, "5.1.4.1"),
        query("ETAB", kNone, kStatusTable, "5.1.4.2"),
        query("GASPSTAB", kNone, kStatusTable, "5.1.5.1"),
        query("GESPSTAB", kNone, kStatusTable, "5.1.5.2"),
        query("GMPSTAB", kNone, kStatusTable, "5.1.5.3"),
        query("GXSPSTAB", kNone, kStatusTable, "5.1.5.4"),
        query("GVSPSTAB", kNone, kStatusTable, "5.1.5.5"),
        command("GVSPSTAB", kStatusTable, "5.1.5.6"),
        // The manual prints 5.1.5.7 (S inputs) as a second ?GVSPSTAB; the
        // name follows ?GSSPSMAX and is a guess.
        provisional(query("GSSPSTAB", kNone, kStatusTable, "5.1.5.7"), kPStatusName),
        provisional(query("BSPEED", kNone, signedValue(), "5.1.6.1"), kPSpeed),
        provisional(query("SPEED", kNone, textValue(kFormat), "5.1.6.2"), kPSpeed),
        provisional(query("IGWG", kNone, signedValue(), "5.1.7.1"), kPActual),
        provisional(query("IFGWG", kNone, textValue(kFormat), "5.1.7.2"), kPActual),
        provisional(query("IREE", kNone, signedValue(), "5.1.7.3"), kPActual),
        provisional(query("PAU", kNone, value(kProgram), "5.1.8.1"), kPProgram),
        provisional(command("PAU", value(kProgram), "5.1.8.2"), kPProgram),
        provisional(query("PNAME", {hex("program", kProgram)},
                          {hex("program", kProgram), text("text", kTextLine)}, "5.1.8.3"),
                    kPProgram),
        provisional(
            command("PNAME", {hex("program", kProgram), text("text", kTextLine)}, "5.1.8.4"),
            kPProgram),
        // 5.1.9 is missing, but 5.4.3.5 describes ?UNIT: an empty reply.
        query("UNIT", kNone, kNone, "5.4.3.5"),

        // 5.2 Programming menu
        query("NF", {hex("program", kProgram), hex("output", kSmall)},
              {signedHex("on"), signedHex("off"), hex("more", kSmall)}, "5.2.1.1"),
        query("NL", kNone, {signedHex("on"), signedHex("off"), hex("earlier", kSmall)}, "5.2.1.2"),
        query("NS", {signedHex("on")}, kCamBoth, "5.2.1.3"),
        actsTwice(query("NN", kNone, kCamBoth, "5.2.1.4")),
        actsTwice(query("NP", kNone, kCamBoth, "5.2.1.5")),
        actsTwice(command(
            "NINS",
            {hex("program", kProgram), hex("output", kSmall), signedHex("on"), signedHex("off")},
            "5.2.1.6")),
        actsTwice(command(
            "NDEL", {hex("program", kProgram), hex("output", kSmall), signedHex("on")}, "5.2.1.7")),
        actsTwice(provisional(command("NC",
                                      {hex("program", kProgram), hex("output", kSmall),
                                       signedHex("oldOn"), signedHex("on"), signedHex("off")},
                                      "5.2.1.8"),
                              kPNc)),
        provisional(query("TZK", {hex("output", kSmall)},
                          {hex("output", kSmall), hex("value", kLong)}, "5.2.2.1"),
                    kPDeadTime),
        provisional(command("TZK", {hex("output", kSmall), hex("value", kLong)}, "5.2.2.2"),
                    kPDeadTime),
        provisional(query("ANAME", {hex("output", kSmall)},
                          {hex("output", kSmall), text("text", kTextLine)}, "5.2.3"),
                    kPOutputName),
        provisional(command("ANAME", {hex("output", kSmall), text("text", kTextLine)}, "5.2.4"),
                    kPOutputName),
        command("PDEL", {hex("program", kProgram)}, "5.2.5"),
        command("PCPY", {hex("target", kProgram), hex("source", kProgram)}, "5.2.6"),
        command("PACPY", {hex("program", kProgram), hex("target", kSmall), hex("source", kSmall)},
                "5.2.7"),
        command("PT", {hex("program", kProgram), hex("type", kSmall)}, "5.2.8"),

        // 5.3.1 Encoder
        query("GEBER", kNone, value(kSmall), "5.3.1.1"),
        command("GEBER", value(kSmall), "5.3.1.2"),
        query("GTXT1", kNone, textValue(kTextLine), "5.3.1.3"),
        query("GTXT2", kNone, textValue(kTextLine), "5.3.1.4"),
        query("GISTHYS", kNone, value(kSmall), "5.3.1.5"),
        command("GISTHYS", value(kSmall), "5.3.1.6"),
        query("GVMAX", kNone, value(kProgram), "5.3.1.7"),
        command("GVMAX", value(kProgram), "5.3.1.8"),
        query("IMUL", kNone, signedValue(), "5.3.1.9"),
        command("IMUL", signedValue(), "5.3.1.10"),
        query("IDIV", kNone, signedValue(), "5.3.1.11"),
        command("IDIV", signedValue(), "5.3.1.12"),
        query("IFOR", kNone, textValue(kFormat), "5.3.1.13"),
        command("IFOR", textValue(kFormat), "5.3.1.14"),
        provisional(query("GSTYP", kNone, value(kSmall), "5.3.1.15.1"), kPEncoder),
        provisional(query("GSSSI", kNone, kSsi, "5.3.1.15.2"), kPEncoder),
        provisional(command("GSSSI", encoderWrite(kSsi), "5.3.1.15.3"), kPEncoder),
        provisional(query("GSPAR", kNone, kParallel, "5.3.1.15.4"), kPEncoder),
        provisional(command("GSPAR", encoderWrite(kParallel), "5.3.1.15.5"), kPEncoder),
        provisional(query("GSINK", kNone, kIncremental, "5.3.1.15.6"), kPEncoder),
        provisional(command("GSINK", encoderWrite(kIncremental), "5.3.1.15.7"), kPEncoder),
        provisional(query("GSMULTI", kNone, kMultiturn, "5.3.1.15.8"), kPEncoder),
        provisional(command("GSMULTI", encoderWrite(kMultiturn), "5.3.1.15.9"), kPEncoder),
        provisional(query("GSPLL", kNone, kPll, "5.3.1.15.10"), kPEncoder),
        provisional(command("GSPLL", encoderWrite(kPll), "5.3.1.15.11"), kPEncoder),
        query("GSTIM", kNone, kTimer, "5.3.1.15.12"),
        command("GSTIM", encoderWrite(kTimer), "5.3.1.15.13"),

        // 5.3.2 Position adaptation
        query("WLIN", kNone, value(kSmall), "5.3.2.1"),
        command("WLIN", value(kSmall), "5.3.2.2"),
        query("WANF", kNone, signedValue(), "5.3.2.3"),
        command("WANF", signedValue(), "5.3.2.4"),
        query("WNULLV", kNone, signedValue(), "5.3.2.5"),
        command("WNULLV", signedValue(), "5.3.2.6"),
        query("WPRE", kNone, signedValue(), "5.3.2.7"),
        command("WPRE", signedValue(), "5.3.2.8"),
        query("WEINPRE", kNone, value(kSmall), "5.3.2.9"),
        command("WEINPRE", value(kSmall), "5.3.2.10"),
        query("WFLPRE", kNone, value(kSmall), "5.3.2.11"),
        command("WFLPRE", value(kSmall), "5.3.2.12"),

        // 5.3.3 Speed (SFAK: 5 decimals, SEXA: 2 decimals, as scaled integers)
        query("SFAK", kNone, value(kLong), "5.3.3.1"),
        command("SFAK", value(kLong), "5.3.3.2"),
        query("SFOR", kNone, textValue(kFormat), "5.3.3.3"),
        command("SFOR", textValue(kFormat), "5.3.3.4"),
        query("S100", kNone, value(kLong), "5.3.3.5"),
        command("S100", value(kLong), "5.3.3.6"),
        query("SEXA", kNone, value(kLong), "5.3.3.7"),
        command("SEXA", value(kLong), "5.3.3.8"),
        query("SSPA", kNone, value(kSmall), "5.3.3.9"),
        command("SSPA", value(kSmall), "5.3.3.10"),
        query("SSPE", kNone, value(kSmall), "5.3.3.11"),
        command("SSPE", value(kSmall), "5.3.3.12"),

        // 5.3.4 Cable length / cycle
        query("GKL", kNone, value(kLong), "5.3.4.1"),
        command("GKL", value(kLong), "5.3.4.2"),
        query("GZYKLSOLL", kNone, value(kLong), "5.3.4.3"),
        command("GZYKLSOLL", value(kLong), "5.3.4.4"),
        query("GZYKLIST", kNone, value(kLong), "5.3.4.5"),

        // 5.3.5 Special outputs
        query("ASICH", kNone, value(kSmall), "5.3.5.1"),
        command("ASICH", value(kSmall), "5.3.5.2"),
        query("GISTAUS", kNone, value(kSmall), "5.3.5.3"),
        command("GISTAUS", value(kSmall), "5.3.5.4"),
        query("GVRAUS", kNone, value(kSmall), "5.3.5.5"),
        command("GVRAUS", value(kSmall), "5.3.5.6"),
        query("GV0AUS", kNone, value(kSmall), "5.3.5.7"),
        command("GV0AUS", value(kSmall), "5.3.5.8"),
        query("GV0SPEED", kNone, value(kLong), "5.3.5.9"),
        command("GV0SPEED", value(kLong), "5.3.5.10"),
        query("ASPEED", kNone, value(kSmall), "5.3.5.11"),
        command("ASPEED", value(kSmall), "5.3.5.12"),
        query("ANOCK", kNone, value(kSmall), "5.3.5.13"),
        command("ANOCK", value(kSmall), "5.3.5.14"),
        query("AMODE", {hex("channel", kSmall)}, kAnalogueMode, "5.3.5.15"),
        command("AMODE", QList<FieldSpec>{hex("channel", kSmall)} + kAnalogueMode, "5.3.5.16"),
        // One 16-bit word per analogue output, as many as the device has.
        query("ANTAB", kNone, {hexWords("values", kWord, -1)}, "5.3.5.17"),

        // 5.3.6 System layout
        query("EMAX", kNone, value(kSmall), "5.3.6.1"),
        command("EMAX", value(kSmall), "5.3.6.2"),
        query("AMAX", kNone, value(kSmall), "5.3.6.3"),
        command("AMAX", value(kSmall), "5.3.6.4"),
        query("GTZKANZ", kNone, value(kSmall), "5.3.6.5"),
        withOkOptional(command("GTZKANZ", value(kSmall), "5.3.6.6")),
        query("GTLOCK", kNone, value(kSmall), "5.3.6.7"),
        command("GTLOCK", value(kSmall), "5.3.6.8"),
        query("GPRGEXT", kNone, value(kSmall), "5.3.6.9"),
        command("GPRGEXT", value(kSmall), "5.3.6.10"),
        query("GPRGEINEXT", kNone, value(kSmall), "5.3.6.11"),
        command("GPRGEINEXT", value(kSmall), "5.3.6.12"),
        query("GPATYP", kNone, {hex("mode", kSmall), signedHex("value")}, "5.3.6.13"),
        command("GPATYP", {hex("mode", kSmall), signedHex("value")}, "5.3.6.14"),

        // 5.4.1 Users, in the form of 7.1.1 (rights bit 7 = user menu)
        actsTwice(query("USER", {hex("index", kSmall)}, kUserFields, "7.1.1.1")),
        command("USER", QList<FieldSpec>{text("oldNumber", kUserNumber)} + kUserFields, "7.1.1.2"),

        // 5.4.2 Clear all / reset
        slow(command("CA", kNone, "5.4.2.1")),
        withoutReply(command("GRESET", kNone, "5.4.2.2")),

        // 5.4.3 Device configuration
        query("GSIO", kNone, value(kSmall), "5.4.3.1"),
        command("GSIO", value(kSmall), "5.4.3.2"),
        query("GNR", kNone, value(kSmall), "5.4.3.3"),
        command("GNR", value(kSmall), "5.4.3.4"),
        query("GANL", kNone, value(kSmall), "5.4.3.6"),
        command("GANL", value(kSmall), "5.4.3.7"),
        command("A0", value(kSmall), "5.4.3.8"),
        query("A1", kNone, value(kSmall), "5.4.3.9"),
        command("A1", value(kSmall), "5.4.3.10"),
        query("A2", kNone, value(kSmall), "5.4.3.11"),
        command("A2", value(kSmall), "5.4.3.12"),
        query("A3", kNone, value(kWord), "5.4.3.13"),
        command("A3", value(kWord), "5.4.3.14"),
        query("A4", kNone, value(kWord), "5.4.3.15"),
        command("A4", value(kWord), "5.4.3.16"),
        query("GTERM", kNone, value(kSmall), "5.4.3.17"),
        command("GTERM", value(kSmall), "5.4.3.18"),

        // 5.4.4 Language, 5.4.5 user texts
        query("GSPRACHE", kNone, value(kSmall), "5.4.4.1"),
        command("GSPRACHE", value(kSmall), "5.4.4.2"),
        query("BTXT", {hex("line", kSmall)}, {hex("line", kSmall), text("text", kTextLine)},
              "5.4.5.1"),
        command("BTXT", {hex("line", kSmall), text("text", kTextLine)}, "5.4.5.2"),

        // 5.4.6 PLC configuration
        query("GBOOST", kNone, value(kSmall), "5.4.6.1"),
        query("GONSPS", kNone, value(kSmall), "5.4.6.2"),
        command("GONSPS", value(kSmall), "5.4.6.3"),
        query("GESPSMAX", kNone, value(kSmall), "5.4.6.4"),
        command("GESPSMAX", value(kSmall), "5.4.6.5"),
        query("GASPSMAX", kNone, value(kSmall), "5.4.6.6"),
        command("GASPSMAX", value(kSmall), "5.4.6.7"),
        query("GMSPSMAX", kNone, value(kSmall), "5.4.6.8"),
        command("GMSPSMAX", value(kSmall), "5.4.6.9"),
        query("GXSPSMAX", kNone, value(kSmall), "5.4.6.10"),
        command("GXSPSMAX", value(kSmall), "5.4.6.11"),
        query("GTSPSMAX", kNone, value(kSmall), "5.4.6.12"),
        command("GTSPSMAX", value(kSmall), "5.4.6.13"),
        query("GVSPSMAX", kNone, value(kSmall), "5.4.6.14"),
        command("GVSPSMAX", value(kSmall), "5.4.6.15"),
        query("GSSPSMAX", kNone, value(kSmall), "5.4.6.16"),
        command("GSSPSMAX", value(kSmall), "5.4.6.17"),

        // 5.4.7 Device info
        query("EPROM", kNone, textValue(kEpromDate), "5.4.7.1"),
        query("GCPUCLK", kNone, value(kSmall), "5.4.7.2"),
        query("GTEMP", kNone, value(kSmall), "5.4.7.3"),
        query("MEEFREE", kNone, value(kLong), "5.4.7.4"),
        query("MEENOCK", kNone, value(kLong), "5.4.7.5"),
        query("GTZKMAX", kNone, value(kLong), "5.4.7.6"),
        query("MRAMMAX", kNone, value(kLong), "5.4.7.7"),
        query("MRAMFREE", kNone, value(kLong), "5.4.7.8"),
        // Titled ?MEES/?MPEE, printed ?MSE/?MPE (notes 10): accept either reply.
        provisional(withReplyAlias(query("MEES", kNone, value(kLong), "5.4.7.9"), "MSE"),
                    kPMemoryName),
        provisional(withReplyAlias(query("MPEE", kNone, value(kLong), "5.4.7.10"), "MPE"),
                    kPMemoryName),
        query("IMIN", kNone, signedValue(), "5.4.7.11"),
        query("IMAX", kNone, signedValue(), "5.4.7.12"),
        query("GPRGMAX", kNone, value(kProgram), "5.4.7.13"),
        query("MEETZK", kNone, value(kLong), "5.4.7.14"),

        // 5.5 PLC menu (notes 5)
        query("GMXSPS", kPlcAddress, kPlcNetwork, "5.5.1"),
        command("GMXSPS", kPlcNetwork, "5.5.2"),
        query("SPSIST", kPlcAddress, signedValue(), "5.5.3"),
        command("SPSIST", kPlcValue, "5.5.4"),
        query("SPSSOLL", kPlcAddress, signedValue(), "5.5.5"),
        command("SPSSOLL", kPlcValue, "5.5.6"),
        query("ETXT", {hex("message", kSmall)}, kErrorText, "5.5.7"),
        command("ETXT", kErrorText, "5.5.8"),

        // 5.6 EEPROM (notes 6). ?EEFFFF answers block FFFF without data.
        query("EE", {hex("block", kWord)}, {hex("block", kWord), binary("data", -1)}, "5.6.1"),
        // Only block 0000 erases and takes long; the link checks the block.
        sendOnce(slow(command("EE", {hex("block", kWord), binary("data", -1)}, "5.6.2"))),

        // 5.7 RAM access
        query("ML", {hex("address", kLong)}, {hex("address", kLong), hex("value", kLong)}, "5.7.1"),
        command("MS", {hex("address", kLong), hex("value", kSmall)}, "5.7.2"),
        command("MW", {hex("address", kLong), hex("value", kWord)}, "5.7.3"),
    };
}

}  // namespace

const QList<CommandSpec>& commandCatalogue() {
    static const QList<CommandSpec> catalogue = buildCatalogue();
    return catalogue;
}

const CommandSpec* findCommand(char kind, QByteArrayView name) {
    for (const CommandSpec& spec : commandCatalogue()) {
        if (spec.kind == kind && name == QByteArrayView(spec.name)) return &spec;
    }
    return nullptr;
}

const CommandSpec* matchRequest(char kind, QByteArrayView body) {
    const CommandSpec* best = nullptr;
    qsizetype bestLength = -1;
    for (const CommandSpec& spec : commandCatalogue()) {
        const QByteArrayView name(spec.name);
        if (spec.kind == kind && name.size() > bestLength && body.startsWith(name)) {
            best = &spec;
            bestLength = name.size();
        }
    }
    return best;
}

}  // namespace cambench::comm
