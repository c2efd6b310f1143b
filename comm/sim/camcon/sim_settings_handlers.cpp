#include "sim_device.h"
#include "sim_handlers.h"

#include "comm/camcon/ascii/catalogue.h"

namespace cambench::comm {

namespace {

// The ranges the manual gives for single-value settings (field "value").
struct Range {
    const char* name;
    qint64 min;
    qint64 max;
    int step = 1;          // counts of 8
    bool nonZero = false;  // gear multiplier: -99999..-1 and 1..99999
};

const QList<Range>& ranges() {
    static const QList<Range> table{
        {"GISTHYS", 0, 125},     {"GVMAX", 0, 9999},       {"IMUL", -99999, 99999, 1, true},
        {"IDIV", 1, 99999},      {"WLIN", 0, 1},           {"WEINPRE", 0, 200},
        {"WFLPRE", 0, 1},        {"SFAK", 1, 99999999},    {"S100", 1, 999999999},
        {"SEXA", 1, 999},        {"SSPA", 0, 2},           {"SSPE", 0, 200},
        {"GKL", 0, 1000},        {"GZYKLSOLL", 0, 100000}, {"ASICH", 0, 200},
        {"GISTAUS", 0, 3},       {"GVRAUS", 0, 200},       {"GV0AUS", 0, 200},
        {"ASPEED", 0, 1},        {"ANOCK", 0, 14},         {"EMAX", 0, 200, 8},
        {"AMAX", 8, 200, 8},     {"GTZKANZ", 0, 200, 8},   {"GTLOCK", 0, 200},
        {"GPRGEXT", 0, 15},      {"GPRGEINEXT", 0, 200},   {"GSIO", 0, 4},
        {"GNR", 0, 63},          {"GANL", 0, 2},           {"GTERM", 0, 1},
        {"GONSPS", 0, 2},        {"GESPSMAX", 0, 200, 8},  {"GASPSMAX", 8, 200, 8},
        {"GMSPSMAX", 0, 248, 8}, {"GXSPSMAX", 0, 248, 8},  {"GTSPSMAX", 0, 248, 8},
        {"GVSPSMAX", 0, 248, 8}, {"GSSPSMAX", 0, 248, 8},
    };
    return table;
}

constexpr qint64 kLastListedEncoder = 0x14;
constexpr qint64 kSpecialEncoder = 0xFF;
constexpr qint64 kMaxAnalogueOffset = 32000;

bool inRange(const SimDevice& d, const QByteArray& name, const Fields& request) {
    const qint64 v = request.num("value");
    if (name == "GEBER") return v <= kLastListedEncoder || v == kSpecialEncoder;
    if (name == "GPATYP") return request.num("mode") <= 2;
    // The simulated hardware has no more outputs or inputs than its profile.
    if (name == "AMAX" && v > d.profile().outputs) return false;
    if (name == "EMAX" && v > d.profile().inputs) return false;
    for (const Range& range : ranges()) {
        if (name != range.name) continue;
        return v >= range.min && v <= range.max && v % range.step == 0 &&
               !(range.nonZero && v == 0);
    }
    return true;
}

// Copies the fields `specs` name from `from`.
Fields pick(const QList<FieldSpec>& specs, const Fields& from) {
    Fields kept;
    for (const FieldSpec& field : specs) {
        const QByteArray name(field.name);
        if (!from.has(name)) continue;
        switch (field.type) {
            case FieldType::Hex:
            case FieldType::SignedHex:
                kept.set(name, from.num(name));
                break;
            case FieldType::HexWords:
                kept.setWords(name, from.words(name));
                break;
            case FieldType::Text:
            case FieldType::TextRest:
            case FieldType::Binary:
            case FieldType::HexBytes:
                kept.setBytes(name, from.bytes(name));
                break;
        }
    }
    return kept;
}

// For writing: creates the entry.
Fields& stored(SimDevice& d, const QByteArray& name, int index = -1) {
    return d.state().settings[{name, index}];
}

// !GSSSI, !GSPAR, ...: the two text lines become ?GTXT1/?GTXT2, the type
// ?GSTYP, and the device now uses the programmable special encoder.
void registerSpecialEncoders(SimDevice& d) {
    for (const char* page : {"GSSSI", "GSPAR", "GSINK", "GSMULTI", "GSPLL", "GSTIM"}) {
        const CommandSpec* query = findCommand(kQuery, page);
        if (!query) continue;
        const QByteArray name(page);
        d.addHandler(kCommand, name, [&d, name, query](const Fields& r) {
            stored(d, name) = pick(query->reply, r);
            stored(d, "GTXT1") = Fields().setBytes("text", r.bytes("text1"));
            stored(d, "GTXT2") = Fields().setBytes("text", r.bytes("text2"));
            stored(d, "GSTYP") = Fields().set("value", r.num("type"));
            stored(d, "GEBER") = Fields().set("value", kSpecialEncoder);
            return SimResult::ok();
        });
    }
}

void registerAnalogueModes(SimDevice& d) {
    const CommandSpec* query = findCommand(kQuery, "AMODE");
    if (!query) return;
    const auto valid = [&d](const Fields& r) {
        const qint64 channel = r.num("channel");
        return channel >= 0 && channel < d.profile().analogChannels;
    };
    d.addHandler(kQuery, "AMODE", [&d, valid](const Fields& r) {
        if (!valid(r)) return SimResult::error(sim_errors::kUnknown);
        return SimResult::data(d.state().settings.value({"AMODE", int(r.num("channel"))}));
    });
    d.addHandler(kCommand, "AMODE", [&d, valid, query](const Fields& r) {
        if (!valid(r) || qAbs(r.num("offset")) > kMaxAnalogueOffset)
            return SimResult::error(sim_errors::kUnknown);
        stored(d, "AMODE", int(r.num("channel"))) = pick(query->reply, r);
        return SimResult::ok();
    });
}

// Every catalogue query without request data that nobody else answers is a
// stored setting (0 until set), and its command, if any, sets it.
void registerGenericSettings(SimDevice& d) {
    for (const CommandSpec& spec : commandCatalogue()) {
        if (spec.kind != kQuery || !spec.request.isEmpty() || spec.replyKind != ReplyKind::Data)
            continue;
        const QByteArray name(spec.name);
        if (!d.hasHandler(kQuery, name)) {
            d.addHandler(kQuery, name, [&d, name](const Fields&) {
                return SimResult::data(d.state().settings.value({name, -1}));
            });
        }
        if (!d.hasHandler(kCommand, name) && findCommand(kCommand, name)) {
            const CommandSpec* query = &spec;
            d.addHandler(kCommand, name, [&d, name, query](const Fields& r) {
                if (!inRange(d, name, r)) return SimResult::error(sim_errors::kUnknown);
                stored(d, name) = pick(query->reply, r);
                return SimResult::ok();
            });
        }
    }
}

}  // namespace

void registerSettingsHandlers(SimDevice& device) {
    registerSpecialEncoders(device);
    registerAnalogueModes(device);
    registerGenericSettings(device);
}

}  // namespace cambench::comm
