// Issue 15: the Compax3 ASCII protocol's text both ways (objects, values,
// requests, answers), independent of the locale (this test also runs with
// LC_ALL=de_DE.UTF-8 and a German QLocale), the object dictionary file
// (a broken one refused with its line) and the parameter file (round trip,
// stable order, hash).
#include "comm/compax3/compax3_objects.h"
#include "comm/compax3/compax3_syntax.h"
#include "comm/engine/cr_line_backend.h"
#include "model/compax3/compax3_dictionary.h"
#include "model/compax3/compax3_parameter_file.h"
#include "model/compax3/compax3_refusals.h"

#include <QLocale>
#include <QTest>

#include <clocale>

using namespace cambench;
using namespace cambench::comm;

class TestCompax3Syntax : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() {
        // A German technician's PC: the decimal separator is ','.
        QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
        std::setlocale(LC_ALL, "de_DE.UTF-8");  // where installed; QLocale alone otherwise
    }

    void objectsAreReadInEveryWayATechnicianWritesThem() {
        const Compax3ObjectId expected{680, 5};
        for (const char* text : {"680.5", "680,5", "o680.5", "O 680,5", "O680,5", " o 680 . 5 ",
                                 "O $2A8,5", "$2a8.$5"}) {
            const Result<Compax3ObjectId> id = parseCompax3Object(QLatin1String(text));
            QVERIFY2(id.ok(), text);
            QCOMPARE(*id, expected);
        }
        QCOMPARE(expected.text(), QStringLiteral("680.5"));
        for (const char* bad : {"680", "680.5.1", "x680.5", "70000.1", "1.300", "", "O"}) {
            const Result<Compax3ObjectId> id = parseCompax3Object(QLatin1String(bad));
            QVERIFY2(!id.ok(), bad);
            QVERIFY(id.error().message.contains(QLatin1String("index.subindex")));
        }
    }

    void numbersAlwaysCarryAPoint() {
        QCOMPARE(compax3NumberText(12.5), QStringLiteral("12.5"));
        QCOMPARE(compax3NumberText(-3), QStringLiteral("-3"));
        QCOMPARE(compax3NumberText(0.001), QStringLiteral("0.001"));
        QCOMPARE(compax3NumberText(1000000), QStringLiteral("1000000"));
        QCOMPARE(compax3NumberText(-0.0), QStringLiteral("0"));
        QCOMPARE(*compax3WireValue(QStringLiteral("12.50"), Compax3Type::Real),
                 QStringLiteral("12.5"));
        QCOMPARE(*compax3WireValue(QStringLiteral("$1f"), Compax3Type::Integer),
                 QStringLiteral("$1F"));
        QCOMPARE(*compax3WireValue(QStringLiteral("1; 2.5;$A"), Compax3Type::Real),
                 QStringLiteral("1;2.5;$A"));
        QCOMPARE(*compax3WireValue(QStringLiteral("Axis 1; left"), Compax3Type::Text),
                 QStringLiteral("\"Axis 1; left\""));
        QCOMPARE(*compax3WireValue(QStringLiteral("\"x\""), Compax3Type::Text),
                 QStringLiteral("\"x\""));
        QCOMPARE(compax3WriteCommand({1901, 1},
                                     *compax3WireValue(QStringLiteral("12.5"), Compax3Type::Real)),
                 QByteArray("O1901,1=12.5"));
    }

    void aGermanCommaIsRefusedWithTheFix() {
        const Result<QString> wire = compax3WireValue(QStringLiteral("12,5"), Compax3Type::Real);
        QVERIFY(!wire.ok());
        QVERIFY2(wire.error().message.contains(QLatin1String("(12.5)")),
                 qPrintable(wire.error().message));
        QVERIFY(!compax3WireValue(QStringLiteral("2.5"), Compax3Type::Integer).ok());
        QVERIFY(!compax3WireValue(QStringLiteral("abc"), Compax3Type::Real).ok());
        QVERIFY(!compax3WireValue(QStringLiteral("a\"b"), Compax3Type::Text).ok());
        Compax3Range range;
        range.min = 0;
        range.max = 100;
        const Result<QString> high =
            compax3WireValue(QStringLiteral("100.5"), Compax3Type::Real, range);
        QVERIFY(!high.ok());
        QVERIFY2(high.error().message.contains(QLatin1String("0 to 100")),
                 qPrintable(high.error().message));
    }

    void valuesCompareAsNumbers() {
        QVERIFY(compax3SameValue(QStringLiteral("12.50"), QStringLiteral("12.5")));
        QVERIFY(compax3SameValue(QStringLiteral("$10"), QStringLiteral("16")));
        QVERIFY(compax3SameValue(QStringLiteral("\"A\""), QStringLiteral("A")));
        QVERIFY(!compax3SameValue(QStringLiteral("1;2"), QStringLiteral("1")));
        QVERIFY(!compax3SameValue(QStringLiteral("12.5"), QStringLiteral("12.6")));
    }

    void requestsAsTheDriveReadsThem() {
        QCOMPARE(compax3RequestLine("O680,5", -1), QByteArray("O680,5\r"));
        QCOMPARE(compax3RequestLine("O680,5", 7), QByteArray("7O680,5\r"));
        QCOMPARE(compax3ReadCommand({402, 2}, true), QByteArray("O402,2$"));
        QCOMPARE(compax3Canonical("o 680 , 5"), QByteArray("O680,5"));
        QCOMPARE(compax3Canonical("o1.4=\"a b\""), QByteArray("O1.4=\"a b\""));
        const std::optional<Compax3Request> hex =
            parseCompax3Request(compax3Canonical("O $0192,2$"));
        QVERIFY(hex);
        QCOMPARE(hex->id, (Compax3ObjectId{402, 2}));
        QVERIFY(hex->hexAnswer);
        const std::optional<Compax3Request> write = parseCompax3Request("O1901.1=12.5");
        QVERIFY(write && write->kind == Compax3Request::Write);
        QCOMPARE(write->value, QStringLiteral("12.5"));
        QVERIFY(parseCompax3Request("_?")->kind == Compax3Request::Info);
        QVERIFY(!parseCompax3Request("O680"));
        QVERIFY(!parseCompax3Request("O680,5$=1"));
    }

    void answersWithAndWithoutTheRs485Mark() {
        QCOMPARE(parseCompax3Reply("12.5")->text, QStringLiteral("12.5"));
        QCOMPARE(parseCompax3Reply("*12.5")->text, QStringLiteral("12.5"));
        QCOMPARE(parseCompax3Reply(">")->kind, Compax3Reply::Ok);
        QCOMPARE(parseCompax3Reply("*>")->kind, Compax3Reply::Ok);
        const Result<Compax3Reply> refused = parseCompax3Reply("*!0004");
        QCOMPARE(refused->kind, Compax3Reply::Error);
        QCOMPARE(refused->code, 4);
        QVERIFY(!parseCompax3Reply("!12").ok());
        QVERIFY(!parseCompax3Reply("").ok());
        QVERIFY(!parseCompax3Reply("1\x01"
                                   "2")
                     .ok());
        QByteArray buffer("12\r\n>\r*!00");
        QCOMPARE(*takeCrLine(buffer), QByteArray("12"));
        QCOMPARE(*takeCrLine(buffer), QByteArray(">"));
        QVERIFY(!takeCrLine(buffer));
    }

    void refusalsNameTheNumberAndItsMeaning() {
        const Error known = compax3RefusalError("O1901,1=5000000", 4);
        QCOMPARE(known.kind, ErrorKind::DeviceError);
        QVERIFY2(known.message.contains(QLatin1String("!0004")), qPrintable(known.message));
        QVERIFY(known.message.contains(QLatin1String("outside the object's range")));
        const Error unknown = compax3RefusalError("O1,1", 0xBEEF);
        QVERIFY2(unknown.message.contains(QLatin1String("!BEEF")), qPrintable(unknown.message));
        QVERIFY(unknown.message.contains(QLatin1String("manual")));
        // The meanings are data (the dictionary file's "refusals"): every
        // number the emulator knows, "no such object" the one that means absent.
        QCOMPARE(compax3Refusals().size(), 6);
        QVERIFY(compax3RefusalSaysAbsent(2));
        QVERIFY(!compax3RefusalSaysAbsent(5));
        QVERIFY(compax3RefusalMeansAbsent(compax3RefusalError("O1901,0", 2)));
        // English under a German locale without the German translation
        // (this test's locale): the CLI's language.
        QCOMPARE(compax3RefusalMeaning(3), QStringLiteral("the object is read-only"));
        QCOMPARE(compax3LastErrorText(0x7320), QStringLiteral("following error ($7320)"));
        QVERIFY(compax3LastErrorText(12345).contains(QLatin1String("$3039")));
    }

    // A loaded dictionary's own "refusals" word the drive's answers and say
    // which means absent; a dictionary without them keeps the shipped ones.
    void aLoadedDictionaryBringsItsRefusals() {
        const Result<Compax3Dictionary> own = Compax3Dictionary::fromJson(
            "{\"format\":\"cambench-compax3-dictionary\",\"version\":1,\"refusals\":["
            "{\"code\":\"0007\",\"meaning\":\"not in this firmware\",\"absent\":true}],"
            "\"objects\":[]}");
        QVERIFY2(own.ok(), qPrintable(own.error().message));
        QCOMPARE(own->refusals().size(), 1);
        const Error refused = compax3RefusalError("O1904,1", 7, own->refusals());
        QVERIFY2(refused.message.contains(QLatin1String("!0007 (not in this firmware)")),
                 qPrintable(refused.message));
        QVERIFY(compax3RefusalMeansAbsent(refused, own->refusals()));
        QVERIFY(!compax3RefusalMeansAbsent(refused));
        QVERIFY(!compax3RefusalMeansAbsent(compax3RefusalError("O1,9", 2), own->refusals()));
        const Result<Compax3Dictionary> objectsOnly = Compax3Dictionary::fromJson(
            "{\"format\":\"cambench-compax3-dictionary\",\"version\":1,\"objects\":[]}");
        QVERIFY2(objectsOnly.ok(), qPrintable(objectsOnly.error().message));
        QCOMPARE(objectsOnly->refusals().size(), compax3Refusals().size());
    }

    void theShippedDictionaryHoldsSection12() {
        const Compax3Dictionary& dictionary = Compax3Dictionary::builtin();
        QVERIFY(dictionary.objects().size() > 190);
        const Compax3ObjectInfo* position = dictionary.find(kCompax3Position);
        QVERIFY(position);
        QCOMPARE(position->access, Compax3Access::ReadOnly);
        QCOMPARE(position->type, Compax3Type::Real);
        QCOMPARE(dictionary.find(kCompax3ControlWord)->access, Compax3Access::Command);
        // 1904.n stores set n, as the public client writes it after a set.
        for (int set : {0, 2, 31})
            QCOMPARE(dictionary.find(compax3StoreSet(set))->access, Compax3Access::WriteOnly);
        // A parameter set holds what a replacement drive needs, never the
        // control word (restoring it would move the axis) or a function.
        const QList<Compax3ObjectId> parameters = dictionary.parameters();
        QVERIFY(parameters.contains(compax3SetTarget(1)));
        QVERIFY(!parameters.contains(kCompax3ControlWord));
        QVERIFY(!parameters.contains(compax3StoreSet(1)));
        QVERIFY(dictionary.groups().contains(QStringLiteral("Set 0 (homing)")));
        QCOMPARE(position->nameIn(QStringLiteral("de")), QStringLiteral("Istposition"));
        QCOMPARE(position->nameIn(QStringLiteral("fr")), QStringLiteral("Actual position"));
        QCOMPARE(dictionary.find(compax3SetTarget(0))->groupIn(QStringLiteral("de")),
                 QStringLiteral("Satz 0 (Referenzfahrt)"));
        QVERIFY(!compax3WireValueFor(dictionary, kCompax3Position, QStringLiteral("1")).ok());
        QVERIFY(!compax3WireValueFor(dictionary, compax3SetMode(1), QStringLiteral("3")).ok());
        QCOMPARE(*compax3WireValueFor(dictionary, {4000, 1}, QStringLiteral("7.25")),
                 QStringLiteral("7.25"));  // unknown objects: by number, any value
    }

    void aBrokenDictionaryIsRefusedWithItsLine() {
        const QByteArray good = R"({"format":"cambench-compax3-dictionary","version":1,
"objects":[
  {"object":"680.5","name":"Actual position","type":"real","access":"ro"},
  {"object":"1901.1","name":"Target","type":"real","access":"rw","min":0,"max":10}
]})";
        const Result<Compax3Dictionary> loaded = Compax3Dictionary::fromJson(good);
        QVERIFY2(loaded.ok(), qPrintable(loaded.error().message));
        QCOMPARE(loaded->objects().size(), 2);
        QCOMPARE(loaded->find({1901, 1})->range.max, std::optional<double>(10));
        QCOMPARE(loaded->find({680, 5})->group, QStringLiteral("Other"));

        QByteArray badType = good;
        badType.replace("\"type\":\"real\",\"access\":\"rw\"",
                        "\"type\":\"float\",\"access\":\"rw\"");
        const Result<Compax3Dictionary> refused = Compax3Dictionary::fromJson(badType);
        QVERIFY(!refused.ok());
        QVERIFY2(refused.error().message.startsWith(QLatin1String("line 4:")),
                 qPrintable(refused.error().message));
        QVERIFY(refused.error().message.contains(QLatin1String("float")));

        QByteArray notJson = good;
        notJson.replace("\"ro\"}", "\"ro\"");
        const Result<Compax3Dictionary> broken = Compax3Dictionary::fromJson(notJson);
        QVERIFY(!broken.ok());
        QVERIFY2(broken.error().message.contains(QLatin1String("line 4")),
                 qPrintable(broken.error().message));

        QByteArray twice = good;
        twice.replace("\"1901.1\"", "\"680.5\"");
        QVERIFY(Compax3Dictionary::fromJson(twice).error().message.contains(
            QLatin1String("a second time")));
    }

    void aParameterFileRoundTripsInStableOrder() {
        Compax3ParameterSet set;
        set.drive.info = QStringLiteral("Compax3 S025V2 F10 I10 T40 V04.02");
        set.drive.serial = QStringLiteral("C3-1");
        set.taken = QDateTime(QDate(2026, 11, 26), QTime(2, 0), Qt::UTC);
        set.toolVersion = QStringLiteral("0.1.0");
        set.values = {{{1901, 10}, QStringLiteral("5")},
                      {{1901, 2}, QStringLiteral("12.5")},
                      {{1, 4}, QStringLiteral("\"x\"")}};
        const QByteArray json = compax3ParametersToJson(set);
        // One object a line, in object order (1901.2 before 1901.10).
        QVERIFY2(json.contains("[\"1901.2\",\"12.5\"],\n        [\"1901.10\",\"5\"]"),
                 json.constData());
        QCOMPARE(compax3ParametersToJson(set), json);
        const Result<Compax3ParameterSet> back = compax3ParametersFromJson(json);
        QVERIFY2(back.ok(), qPrintable(back.error().message));
        QCOMPARE(back->drive.type(), QStringLiteral("S025V2"));
        QCOMPARE(back->values.size(), 3);
        QCOMPARE(back->values.at(0).id, (Compax3ObjectId{1, 4}));
        QCOMPARE(back->values.at(2).value, QStringLiteral("5"));
        QCOMPARE(back->taken, set.taken);

        QByteArray changed = json;
        changed.replace("\"12.5\"", "\"13.5\"");
        const Result<Compax3ParameterSet> tampered = compax3ParametersFromJson(changed);
        QVERIFY(!tampered.ok());
        QVERIFY2(tampered.error().message.contains(QLatin1String("SHA-256")) ||
                     tampered.error().message.contains(QLatin1String("changed")),
                 qPrintable(tampered.error().message));
        QVERIFY(!compax3ParametersFromJson(R"({"format":"cambench-mc1-backup","version":1})").ok());
    }

    void aFileNeverMovesTheAxisWhateverTheDictionarySays() {
        // A loaded dictionary that calls the control word and a set store
        // parameters cannot lift the built-in list; it can add to it.
        const QByteArray lax = R"({"format":"cambench-compax3-dictionary","version":1,
            "family":"compax3","objects":[
            {"object":"1100.3","name":"cw","type":"integer","access":"rw"},
            {"object":"1904.2","name":"store","type":"integer","access":"rw"},
            {"object":"1901.1","name":"t","type":"real","access":"rw"},
            {"object":"4711.1","name":"go","type":"integer","access":"cmd"}]})";
        const Result<Compax3Dictionary> loaded = Compax3Dictionary::fromJson(lax);
        QVERIFY2(loaded.ok(), qPrintable(loaded.error().message));
        QVERIFY(compax3NeverFromAFile(*loaded, kCompax3ControlWord)
                    .contains(QLatin1String("control word")));
        QVERIFY(
            compax3NeverFromAFile(*loaded, compax3StoreSet(2)).contains(QLatin1String("function")));
        QVERIFY(compax3IsControlWord(*loaded, {4711, 1}));
        QVERIFY(compax3NeverFromAFile(*loaded, compax3SetTarget(1)).isEmpty());
        QVERIFY(compax3NeverFromAFile(Compax3Dictionary::builtin(), compax3SetTarget(1)).isEmpty());
    }

    void aParameterFileRecordsObjectsNotOnTheDrive() {
        Compax3ParameterSet set;
        set.drive.info = QStringLiteral("Compax3 S025V2 F10 I10 T40 V04.02");
        set.taken =
            QDateTime::fromString(QStringLiteral("2026-01-02T03:04:05.000Z"), Qt::ISODateWithMs);
        set.values = {{compax3SetTarget(1), QStringLiteral("12.5")}};
        set.absent = {compax3SetVelocity(0), compax3SetTarget(0)};
        const QByteArray json = compax3ParametersToJson(set);
        QVERIFY(json.contains("\"absent\""));
        const Result<Compax3ParameterSet> back = compax3ParametersFromJson(json);
        QVERIFY2(back.ok(), qPrintable(back.error().message));
        QCOMPARE(back->absent,
                 (QList<Compax3ObjectId>{compax3SetTarget(0), compax3SetVelocity(0)}));
        QCOMPARE(back->values.size(), 1);
        // A file without absent objects has no "absent" key (files stay as they were).
        set.absent.clear();
        QVERIFY(!compax3ParametersToJson(set).contains("\"absent\""));
    }
};

QTEST_GUILESS_MAIN(TestCompax3Syntax)
#include "tst_compax3_syntax.moc"
