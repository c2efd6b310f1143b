#include "comm/camcon/ascii/catalogue.h"

#include <QtTest>

#include <set>

using namespace cambench::comm;

namespace {

QByteArray label(const CommandSpec& spec) {
    return spec.kind + QByteArray(spec.name);
}

const CommandSpec* find(const QByteArray& labelText) {
    return findCommand(labelText.at(0), QByteArrayView(labelText).sliced(1));
}

bool isRest(const FieldSpec& field) {
    return field.type == FieldType::TextRest || field.type == FieldType::HexBytes ||
           (field.type == FieldType::Binary && field.width < 0) ||
           (field.type == FieldType::HexWords && field.count < 0);
}

// Every command of manual section 5 (with the typo fixes of notes 10), the
// provisional ones of notes 3, and !C0/!C1 of 4.3.
const QList<QByteArray> kManualCommands{
    "!C0",
    "!C1",
    // 5.1
    "?ERR",
    "!ERR",
    "?AUTO",
    "?ATAB",
    "?ETAB",
    "?GASPSTAB",
    "?GESPSTAB",
    "?GMPSTAB",
    "?GXSPSTAB",
    "?GVSPSTAB",
    "!GVSPSTAB",
    "?BSPEED",
    "?SPEED",
    "?IGWG",
    "?IFGWG",
    "?IREE",
    "?PAU",
    "!PAU",
    "?PNAME",
    "!PNAME",
    "?UNIT",
    // 5.2
    "?NF",
    "?NL",
    "?NS",
    "?NN",
    "?NP",
    "!NINS",
    "!NDEL",
    "!NC",
    "?TZK",
    "!TZK",
    "?ANAME",
    "!ANAME",
    "!PDEL",
    "!PCPY",
    "!PACPY",
    "!PT",
    // 5.3
    "?GEBER",
    "!GEBER",
    "?GTXT1",
    "?GTXT2",
    "?GISTHYS",
    "!GISTHYS",
    "?GVMAX",
    "!GVMAX",
    "?IMUL",
    "!IMUL",
    "?IDIV",
    "!IDIV",
    "?IFOR",
    "!IFOR",
    "?GSTYP",
    "?GSSSI",
    "!GSSSI",
    "?GSPAR",
    "!GSPAR",
    "?GSINK",
    "!GSINK",
    "?GSMULTI",
    "!GSMULTI",
    "?GSPLL",
    "!GSPLL",
    "?GSTIM",
    "!GSTIM",
    "?WLIN",
    "!WLIN",
    "?WANF",
    "!WANF",
    "?WNULLV",
    "!WNULLV",
    "?WPRE",
    "!WPRE",
    "?WEINPRE",
    "!WEINPRE",
    "?WFLPRE",
    "!WFLPRE",
    "?SFAK",
    "!SFAK",
    "?SFOR",
    "!SFOR",
    "?S100",
    "!S100",
    "?SEXA",
    "!SEXA",
    "?SSPA",
    "!SSPA",
    "?SSPE",
    "!SSPE",
    "?GKL",
    "!GKL",
    "?GZYKLSOLL",
    "!GZYKLSOLL",
    "?GZYKLIST",
    "?ASICH",
    "!ASICH",
    "?GISTAUS",
    "!GISTAUS",
    "?GVRAUS",
    "!GVRAUS",
    "?GV0AUS",
    "!GV0AUS",
    "?GV0SPEED",
    "!GV0SPEED",
    "?ASPEED",
    "!ASPEED",
    "?ANOCK",
    "!ANOCK",
    "?AMODE",
    "!AMODE",
    "?ANTAB",
    "?EMAX",
    "!EMAX",
    "?AMAX",
    "!AMAX",
    "?GTZKANZ",
    "!GTZKANZ",
    "?GTLOCK",
    "!GTLOCK",
    "?GPRGEXT",
    "!GPRGEXT",
    "?GPRGEINEXT",
    "!GPRGEINEXT",
    "?GPATYP",
    "!GPATYP",
    // 5.4
    "?USER",
    "!USER",
    "!CA",
    "!GRESET",
    "?GSIO",
    "!GSIO",
    "?GNR",
    "!GNR",
    "?GANL",
    "!GANL",
    "!A0",
    "?A1",
    "!A1",
    "?A2",
    "!A2",
    "?A3",
    "!A3",
    "?A4",
    "!A4",
    "?GTERM",
    "!GTERM",
    "?GSPRACHE",
    "!GSPRACHE",
    "?BTXT",
    "!BTXT",
    "?GBOOST",
    "?GONSPS",
    "!GONSPS",
    "?GESPSMAX",
    "!GESPSMAX",
    "?GASPSMAX",
    "!GASPSMAX",
    "?GMSPSMAX",
    "!GMSPSMAX",
    "?GXSPSMAX",
    "!GXSPSMAX",
    "?GTSPSMAX",
    "!GTSPSMAX",
    "?GVSPSMAX",
    "!GVSPSMAX",
    "?GSSPSMAX",
    "!GSSPSMAX",
    "?EPROM",
    "?GCPUCLK",
    "?GTEMP",
    "?MEEFREE",
    "?MEENOCK",
    "?GTZKMAX",
    "?MRAMMAX",
    "?MRAMFREE",
    "?MEES",
    "?MPEE",
    "?IMIN",
    "?IMAX",
    "?GPRGMAX",
    "?MEETZK",
    // 5.5 .. 5.7
    "?GMXSPS",
    "!GMXSPS",
    "?SPSIST",
    "!SPSIST",
    "?SPSSOLL",
    "!SPSSOLL",
    "?ETXT",
    "!ETXT",
    "?EE",
    "!EE",
    "?ML",
    "!MS",
    "!MW",
};

const QList<QByteArray> kProvisional{
    "?BSPEED", "?SPEED", "?IGWG",  "?IFGWG",   "?IREE",    "?PAU",   "!PAU",   "?PNAME", "!PNAME",
    "!NC",     "?TZK",   "!TZK",   "?ANAME",   "!ANAME",   "?GSTYP", "?GSSSI", "!GSSSI", "?GSPAR",
    "!GSPAR",  "?GSINK", "!GSINK", "?GSMULTI", "!GSMULTI", "?GSPLL", "!GSPLL",
};

}  // namespace

class TestCatalogue : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void containsEveryManualCommand();
    void hasNoDuplicateCommands();
    void everyRowNamesItsSection();
    void marksProvisionalFormats();
    void appliesTypoFixesOfNotes();
    void marksSlowAndSilentCommands();
    void fieldNamesAreUniqueAndRestFieldsComeLast();
    void fieldWidthsFollowNormalisedTable();
    void singleValueSettingsUseValueOrTextOnBothSides();
    void userCommandsCarryRightsAndBinaryAccess();
    void findCommandReturnsNullForUnknownNames();
    void matchRequestPrefersLongestName_data();
    void matchRequestPrefersLongestName();
    void noCommandNameIsPrefixOfAnotherOfSameKind();
};

void TestCatalogue::containsEveryManualCommand() {
    for (const QByteArray& command : kManualCommands) {
        QVERIFY2(find(command) != nullptr, command.constData());
    }
}

void TestCatalogue::hasNoDuplicateCommands() {
    std::set<QByteArray> seen;
    for (const CommandSpec& spec : commandCatalogue()) {
        QVERIFY2(seen.insert(label(spec)).second, label(spec).constData());
    }
}

void TestCatalogue::everyRowNamesItsSection() {
    for (const CommandSpec& spec : commandCatalogue()) {
        QVERIFY2(spec.section && QByteArray(spec.section).size() >= 3, label(spec).constData());
        QVERIFY2(spec.kind == '?' || spec.kind == '!', label(spec).constData());
        QVERIFY2(spec.replyKind != ReplyKind::Data || spec.kind == '?', label(spec).constData());
    }
}

void TestCatalogue::marksProvisionalFormats() {
    for (const QByteArray& command : kProvisional) {
        const CommandSpec* spec = find(command);
        QVERIFY2(spec && spec->provisional, command.constData());
        // It names its reading (comm/camcon/README.md), for check's report.
        QVERIFY2(QByteArray(spec->provisional).startsWith("provisional: P-ASCII-"),
                 command.constData());
    }
    QVERIFY(!find("?NF")->provisional);
    QVERIFY(!find("?GSTIM")->provisional);
}

void TestCatalogue::appliesTypoFixesOfNotes() {
    for (const char* command :
         {"!GEBER", "!IMUL", "!IDIV", "!WLIN", "!WPRE", "!GANL", "!SPSSOLL"}) {
        const CommandSpec* spec = find(command);
        QVERIFY2(spec && spec->replyKind == ReplyKind::Ok, command);
    }
    QVERIFY(find("!SPSSOOL") == nullptr);
    QVERIFY(find("!GTZKANZ")->okOptional);
    QVERIFY(!find("!AMAX")->okOptional);
    QCOMPARE(find("?MEES")->replyAliases, QList<QByteArray>{"MSE"});
    QCOMPARE(find("?MPEE")->replyAliases, QList<QByteArray>{"MPE"});
}

void TestCatalogue::marksSlowAndSilentCommands() {
    QCOMPARE(find("!CA")->timeout, TimeoutClass::Long);
    QCOMPARE(find("!EE")->timeout, TimeoutClass::Long);
    QCOMPARE(find("?EE")->timeout, TimeoutClass::Normal);
    QCOMPARE(find("!GRESET")->replyKind, ReplyKind::None);
    for (const CommandSpec& spec : commandCatalogue()) {
        if (spec.timeout == TimeoutClass::Long) QVERIFY2(spec.kind == '!', label(spec).constData());
    }
}

void TestCatalogue::fieldNamesAreUniqueAndRestFieldsComeLast() {
    for (const CommandSpec& spec : commandCatalogue()) {
        for (const QList<FieldSpec>* list : {&spec.request, &spec.reply}) {
            std::set<QByteArray> names;
            for (int i = 0; i < list->size(); ++i) {
                const FieldSpec& field = list->at(i);
                const QByteArray where = label(spec) + "." + field.name;
                QVERIFY2(names.insert(field.name).second, where.constData());
                QVERIFY2(!isRest(field) || i == list->size() - 1, where.constData());
                if (field.type == FieldType::Hex || field.type == FieldType::SignedHex ||
                    field.type == FieldType::HexWords) {
                    QVERIFY2(field.width >= 1 && field.width <= 8, where.constData());
                }
            }
        }
    }
}

void TestCatalogue::fieldWidthsFollowNormalisedTable() {
    auto field = [](const char* command, bool reply, const char* name) -> FieldSpec {
        const CommandSpec* spec = find(command);
        for (const FieldSpec& f : reply ? spec->reply : spec->request) {
            if (QByteArray(f.name) == name) return f;
        }
        return {"", FieldType::Hex, 0};
    };
    QCOMPARE(field("?NF", false, "program").width, 4);
    QCOMPARE(field("?NF", false, "output").width, 2);
    QCOMPARE(field("?NF", true, "on").type, FieldType::SignedHex);
    QCOMPARE(field("?NF", true, "on").width, 8);
    QCOMPARE(field("?GPRGMAX", true, "value").width, 4);
    QCOMPARE(field("?GVMAX", true, "value").width, 4);
    QCOMPARE(field("?GKL", true, "value").width, 8);
    QCOMPARE(field("?SFAK", true, "value").width, 8);
    QCOMPARE(field("?IMUL", true, "value").type, FieldType::SignedHex);
    QCOMPARE(field("?A3", true, "value").width, 4);
    QCOMPARE(field("?AMODE", true, "offset").type, FieldType::SignedHex);
    QCOMPARE(field("?AMODE", true, "offset").width, 4);
    QCOMPARE(field("?IFOR", true, "text").width, 10);
    QCOMPARE(field("?GTXT1", true, "text").width, 22);
    QCOMPARE(field("?EPROM", true, "text").width, 11);
    QCOMPARE(field("?EE", false, "block").width, 4);
    QCOMPARE(field("?EE", true, "data").type, FieldType::Binary);
    QCOMPARE(field("?EE", true, "data").width, -1);
    const FieldSpec symbols = field("?GMXSPS", true, "symbols");
    QCOMPARE(symbols.type, FieldType::HexWords);
    QCOMPARE(symbols.width, 4);
    QCOMPARE(symbols.count, 30);
    QCOMPARE(field("?ATAB", true, "data").type, FieldType::HexBytes);
    QCOMPARE(field("?AUTO", true, "text").type, FieldType::TextRest);
}

void TestCatalogue::singleValueSettingsUseValueOrTextOnBothSides() {
    int checked = 0;
    for (const CommandSpec& spec : commandCatalogue()) {
        if (spec.kind != '?' || !spec.request.isEmpty() || spec.reply.size() != 1) continue;
        const FieldSpec& reply = spec.reply.first();
        if (reply.type == FieldType::HexBytes || reply.type == FieldType::HexWords)
            continue;  // tables
        const QByteArray expected =
            reply.type == FieldType::Text || reply.type == FieldType::TextRest ? "text" : "value";
        QVERIFY2(QByteArray(reply.name) == expected, label(spec).constData());
        const CommandSpec* write = findCommand('!', spec.name);
        if (write && !write->request.isEmpty()) {  // !ERR resets, it writes no value
            QCOMPARE(write->request.size(), 1);
            QVERIFY2(QByteArray(write->request.first().name) == expected,
                     label(*write).constData());
            QCOMPARE(write->request.first().width, reply.width);
            QCOMPARE(write->request.first().type, reply.type);
        }
        ++checked;
    }
    QVERIFY(checked > 50);
}

void TestCatalogue::userCommandsCarryRightsAndBinaryAccess() {
    const CommandSpec* query = find("?USER");
    const CommandSpec* write = find("!USER");
    QCOMPARE(query->section, "7.1.1.1");
    QCOMPARE(query->request.size(), 1);
    QCOMPARE(query->reply.size(), 5);
    QCOMPARE(query->reply[2].type, FieldType::Binary);
    QCOMPARE(query->reply[2].width, 32);
    QCOMPARE(QByteArray(query->reply[4].name), QByteArray("rights"));
    QCOMPARE(query->reply[4].width, 8);  // room for bit 7 (user menu) and more
    QCOMPARE(QByteArray(write->request[0].name), QByteArray("oldNumber"));
    QCOMPARE(write->request.mid(1).size(), query->reply.size());
}

void TestCatalogue::findCommandReturnsNullForUnknownNames() {
    QVERIFY(findCommand('?', "NOPE") == nullptr);
    QVERIFY(findCommand('?', "N") == nullptr);
    QVERIFY(findCommand('!', "NF") == nullptr);  // ?NF only
    QVERIFY(findCommand(':', "NF") == nullptr);
}

void TestCatalogue::matchRequestPrefersLongestName_data() {
    QTest::addColumn<char>("kind");
    QTest::addColumn<QByteArray>("body");
    QTest::addColumn<QByteArray>("expected");  // empty = no match
    QTest::newRow("NF") << '?' << QByteArray("NF000003") << QByteArray("NF");
    QTest::newRow("EE block") << '?' << QByteArray("EE0001") << QByteArray("EE");
    QTest::newRow("EE binary") << '!' << QByteArray("EE0001\x20\x00", 8) << QByteArray("EE");
    QTest::newRow("EPROM") << '?' << QByteArray("EPROM") << QByteArray("EPROM");
    QTest::newRow("ERR") << '?' << QByteArray("ERR") << QByteArray("ERR");
    QTest::newRow("A1") << '!' << QByteArray("A17F") << QByteArray("A1");
    QTest::newRow("AMAX") << '!' << QByteArray("AMAX08") << QByteArray("AMAX");
    QTest::newRow("GSSSI") << '?' << QByteArray("GSSSI") << QByteArray("GSSSI");
    QTest::newRow("GSSPSMAX") << '?' << QByteArray("GSSPSMAX") << QByteArray("GSSPSMAX");
    QTest::newRow("GZYKLIST") << '?' << QByteArray("GZYKLIST") << QByteArray("GZYKLIST");
    QTest::newRow("unknown") << '?' << QByteArray("XYZ") << QByteArray();
    QTest::newRow("empty") << '?' << QByteArray() << QByteArray();
    QTest::newRow("kind matters") << '!' << QByteArray("NF000003") << QByteArray();
}

void TestCatalogue::matchRequestPrefersLongestName() {
    QFETCH(char, kind);
    QFETCH(QByteArray, body);
    QFETCH(QByteArray, expected);
    const CommandSpec* spec = matchRequest(kind, body);
    if (expected.isEmpty()) {
        QVERIFY(spec == nullptr);
    } else {
        QVERIFY(spec != nullptr);
        QCOMPARE(spec->kind, kind);
        QCOMPARE(QByteArray(spec->name), expected);
    }
}

void TestCatalogue::noCommandNameIsPrefixOfAnotherOfSameKind() {
    // With no such pair, a request or reply name is found by prefix alone,
    // whatever data follows.
    const QList<CommandSpec>& catalogue = commandCatalogue();
    for (const CommandSpec& a : catalogue) {
        for (const CommandSpec& b : catalogue) {
            if (&a == &b || a.kind != b.kind) continue;
            const QByteArray nameA(a.name);
            QVERIFY2(!QByteArray(b.name).startsWith(nameA),
                     qPrintable(label(a) + " prefixes " + label(b)));
        }
    }
}

QTEST_GUILESS_MAIN(TestCatalogue)
#include "tst_catalogue.moc"
