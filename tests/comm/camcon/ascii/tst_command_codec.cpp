#include "comm/camcon/ascii/command_codec.h"
#include "comm/camcon/ascii/device_errors.h"
#include "comm/camcon/ascii/stream_decoder.h"

#include <QtTest>

using namespace cambench;
using namespace cambench::comm;

Q_DECLARE_METATYPE(cambench::comm::Fields)

namespace {

// Sample values per variant: 0 = largest values and full texts, 1 = smallest
// values and empty texts, 2 = mixed values with CR, ESC and LF in texts and
// binary data (exercising the frame escapes).
qint64 sampleNumber(const FieldSpec& field, int variant, int index) {
    const int bits = 4 * field.width;
    const bool isSigned = field.type == FieldType::SignedHex;
    const qint64 max = isSigned ? (qint64(1) << (bits - 1)) - 1 : (qint64(1) << bits) - 1;
    const qint64 min = isSigned ? -(qint64(1) << (bits - 1)) : 0;
    switch (variant) {
        case 0:
            return isSigned ? min : max;
        case 1:
            return isSigned ? max : min;
        default: {
            const qint64 span = max - min + 1;
            return min + (0x5A3C96E1LL + 7919LL * index) % span;
        }
    }
}

QByteArray sampleBytes(int size, int variant) {
    static const char kSpecial[] = {'\r', '\x1b', '\n', '\0', ':', '?', '!'};
    QByteArray bytes;
    for (int i = 0; i < size; ++i) {
        bytes.append(variant == 2 && i % 3 == 0 ? kSpecial[(i / 3) % sizeof kSpecial]
                                                : char(0x20 + (i * 37 + variant) % 200));
    }
    return bytes;
}

QByteArray sampleText(int maxLength, int variant) {
    if (variant == 1) return {};
    QByteArray text;
    static const char kChars[] = "Ab3 #.,\r\x1b\n-Zz9";
    const int length = variant == 0 ? maxLength : qMin(maxLength, 7);
    for (int i = 0; i < length; ++i) text.append(kChars[(i + variant) % (sizeof kChars - 1)]);
    return text;
}

Fields sampleFields(const QList<FieldSpec>& specs, int variant) {
    Fields fields;
    for (int i = 0; i < specs.size(); ++i) {
        const FieldSpec& field = specs[i];
        switch (field.type) {
            case FieldType::Hex:
            case FieldType::SignedHex:
                fields.set(field.name, sampleNumber(field, variant, i));
                break;
            case FieldType::Text:
                fields.setBytes(field.name, sampleText(field.width - 1, variant));
                break;
            case FieldType::TextRest:
                fields.setBytes(field.name, sampleText(12, variant));
                break;
            case FieldType::Binary:
                fields.setBytes(
                    field.name,
                    sampleBytes(
                        field.width >= 0 ? field.width : (variant == 1 ? 0 : 90 + variant * 19),
                        variant));
                break;
            case FieldType::HexBytes:
                fields.setBytes(field.name, sampleBytes(variant == 1 ? 0 : 25, variant));
                break;
            case FieldType::HexWords: {
                const int count = field.count >= 0 ? field.count : (variant == 1 ? 0 : 5 + variant);
                QList<qint64> words;
                for (int w = 0; w < count; ++w) {
                    words.append(variant == 0   ? 0xFFFF
                                 : variant == 1 ? 0
                                                : (w * 4099 + 17) & 0xFFFF);
                }
                fields.setWords(field.name, words);
                break;
            }
        }
    }
    return fields;
}

const CommandSpec& spec(char kind, const char* name) {
    const CommandSpec* found = findCommand(kind, name);
    Q_ASSERT(found);
    return *found;
}

Frame replyFrame(const QByteArray& body) {
    Frame frame;
    frame.lead = ':';
    frame.body = body;
    return frame;
}

// Sends `frame` through encodeFrame and a fresh decoder: the frame that arrives.
std::optional<Frame> overTheWire(const Frame& frame, const QByteArray& leads) {
    StreamDecoder decoder(frame.address ? Framing::Multiuser : Framing::Standard, leads);
    const QList<DecodeEvent> events = decoder.feed(encodeFrame(frame));
    if (events.size() != 1 || events[0].kind != DecodeEvent::FrameOk) return std::nullopt;
    return events[0].frame;
}

void addCatalogueRows() {
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("variant");
    const QList<CommandSpec>& catalogue = commandCatalogue();
    for (int i = 0; i < catalogue.size(); ++i) {
        for (int variant = 0; variant < 3; ++variant) {
            QTest::addRow("%c%s/%d", catalogue[i].kind, catalogue[i].name, variant) << i << variant;
        }
    }
}

}  // namespace

class TestCommandCodec : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void everyRequestRoundTripsThroughTheWire_data();
    void everyRequestRoundTripsThroughTheWire();
    void everyReplyRoundTripsThroughTheWire_data();
    void everyReplyRoundTripsThroughTheWire();
    void everyCommandRecognisesItsErrorReply_data();
    void everyCommandRecognisesItsErrorReply();

    void manualVectorsEncodeAsRequests();
    void manualVectorsMatchAsReplies();
    void errorCodeIsSignedThirtyTwoBits();
    void notUnderstoodCarriesEpromDate();
    void repliesToOtherCommandsAreUnrelated();
    void wrongDataIsMalformed();
    void okReplyMustSayOkUnlessOptional();
    void replyAliasIsAccepted();
    void silentCommandTreatsEveryReplyAsUnrelated();

    void signedFieldsAreSignExtended();
    void decodeAcceptsLowerCaseHex();
    void decodeRejectsTrailingData();
    void textsLoseTheirNulPadding();
    void valueOutsideWidthIsInvalidDataNamingTheField_data();
    void valueOutsideWidthIsInvalidDataNamingTheField();
    void missingValuesEncodeAsZeroOrEmpty();
    void requestOfWrongCommandIsRejected();
    void deviceErrorTextsCoverManualList();
};

void TestCommandCodec::everyRequestRoundTripsThroughTheWire_data() {
    addCatalogueRows();
}

void TestCommandCodec::everyRequestRoundTripsThroughTheWire() {
    QFETCH(int, index);
    QFETCH(int, variant);
    const CommandSpec& command = commandCatalogue().at(index);
    const Fields fields = sampleFields(command.request, variant);

    const Result<QByteArray> body = encodeRequestBody(command, fields);
    QVERIFY2(body.ok(), qPrintable(body.error().message));
    Frame frame;
    frame.lead = command.kind;
    frame.body = *body;
    if (variant == 2) frame.address = MultiuserAddress{63, 12, 40};
    const std::optional<Frame> received = overTheWire(frame, "?!");
    QVERIFY(received.has_value());
    QCOMPARE(*received, frame);

    const CommandSpec* matched = matchRequest(received->lead, received->body);
    QCOMPARE(matched, &command);
    const Result<Fields> decoded = decodeRequestFields(*matched, received->body);
    QVERIFY2(decoded.ok(), qPrintable(decoded.error().message));
    QCOMPARE(*decoded, fields);
}

void TestCommandCodec::everyReplyRoundTripsThroughTheWire_data() {
    addCatalogueRows();
}

void TestCommandCodec::everyReplyRoundTripsThroughTheWire() {
    QFETCH(int, index);
    QFETCH(int, variant);
    const CommandSpec& command = commandCatalogue().at(index);
    Fields fields;
    QByteArray body;
    switch (command.replyKind) {
        case ReplyKind::Data: {
            fields = sampleFields(command.reply, variant);
            const Result<QByteArray> encoded = encodeReplyBody(command, fields);
            QVERIFY2(encoded.ok(), qPrintable(encoded.error().message));
            body = *encoded;
            break;
        }
        case ReplyKind::Ok:
            body = okReplyBody(command);
            break;
        case ReplyKind::None:
            QVERIFY(!encodeReplyBody(command, {}).ok());
            QCOMPARE(matchReply(command, replyFrame(okReplyBody(command))).kind,
                     ReplyMatch::Unrelated);
            return;
    }
    Frame frame = replyFrame(body);
    if (variant == 2) frame.address = MultiuserAddress{12, 63, 40};
    const std::optional<Frame> received = overTheWire(frame, ":");
    QVERIFY(received.has_value());

    const ReplyMatch match = matchReply(command, *received);
    QVERIFY2(match.kind == ReplyMatch::Matches, qPrintable(match.detail));
    QCOMPARE(match.fields, fields);
}

void TestCommandCodec::everyCommandRecognisesItsErrorReply_data() {
    addCatalogueRows();
}

void TestCommandCodec::everyCommandRecognisesItsErrorReply() {
    QFETCH(int, index);
    QFETCH(int, variant);
    const CommandSpec& command = commandCatalogue().at(index);
    const qint32 code = QList<qint32>{-43, -1, 2147483647}.at(variant);
    const ReplyMatch match = matchReply(command, replyFrame(errorReplyBody(command, code)));
    QCOMPARE(match.kind, ReplyMatch::DeviceError);
    QCOMPARE(match.errorCode, code);
}

void TestCommandCodec::manualVectorsEncodeAsRequests() {
    auto wire = [](char kind, const char* name, const Fields& fields) {
        Frame frame;
        frame.lead = kind;
        frame.body = encodeRequestBody(spec(kind, name), fields).value();
        return encodeFrame(frame);
    };
    QCOMPARE(wire('?', "IFGWG", {}), QByteArray("?IFGWG4C\r\n"));
    QCOMPARE(wire('?', "EE", {{"block", 1}}), QByteArray("?EE000175\r\n"));
    Fields emptyBlock{{"block", 5}};
    emptyBlock.setBytes("data", QByteArray());
    QCOMPARE(wire('!', "EE", emptyBlock), QByteArray("!EE00058F\r\n"));
}

void TestCommandCodec::manualVectorsMatchAsReplies() {
    StreamDecoder decoder(Framing::Standard, ":");
    const QList<DecodeEvent> events =
        decoder.feed(":IFOROKFB\r\n:EEOKA1\r\n:EEFFFF23\r\n:EEERRFFFFFFD535\r\n");
    QCOMPARE(events.size(), 4);

    QCOMPARE(matchReply(spec('!', "IFOR"), events[0].frame).kind, ReplyMatch::Matches);
    QCOMPARE(matchReply(spec('!', "EE"), events[1].frame).kind, ReplyMatch::Matches);

    const ReplyMatch end = matchReply(spec('?', "EE"), events[2].frame);
    QCOMPARE(end.kind, ReplyMatch::Matches);
    QCOMPARE(end.fields.num("block"), 0xFFFF);
    QCOMPARE(end.fields.bytes("data"), QByteArray());

    const ReplyMatch error = matchReply(spec('!', "EE"), events[3].frame);
    QCOMPARE(error.kind, ReplyMatch::DeviceError);
    QCOMPARE(error.errorCode, -43);
}

void TestCommandCodec::errorCodeIsSignedThirtyTwoBits() {
    const CommandSpec& nf = spec('?', "NF");
    QCOMPARE(matchReply(nf, replyFrame("NFERR7FFFFFFF")).errorCode, 2147483647);
    QCOMPARE(matchReply(nf, replyFrame("NFERR80000000")).errorCode,
             std::numeric_limits<qint32>::min());
    QCOMPARE(errorReplyBody(nf, -43), QByteArray("NFERRFFFFFFD5"));
    // ?ERR's own reply starts with its name "ERR": the data still decides.
    const ReplyMatch status = matchReply(spec('?', "ERR"), replyFrame("ERR04"));
    QCOMPARE(status.kind, ReplyMatch::Matches);
    QCOMPARE(status.fields.num("value"), 4);
    QCOMPARE(matchReply(spec('?', "ERR"), replyFrame("ERRERRFFFFFFFF")).errorCode, -1);
}

void TestCommandCodec::notUnderstoodCarriesEpromDate() {
    const QByteArray body = notUnderstoodBody("11.10.1994");
    QCOMPARE(body, QByteArray("Z11.10.1994\0", 12));
    const ReplyMatch match = matchReply(spec('?', "GSPLL"), replyFrame(body));
    QCOMPARE(match.kind, ReplyMatch::NotUnderstood);
    QCOMPARE(match.eprom, QByteArray("11.10.1994"));
}

void TestCommandCodec::repliesToOtherCommandsAreUnrelated() {
    const CommandSpec& nf = spec('?', "NF");
    QCOMPARE(matchReply(nf, replyFrame("NL0000000A0000001401")).kind, ReplyMatch::Unrelated);
    QCOMPARE(matchReply(nf, replyFrame("EEOK")).kind, ReplyMatch::Unrelated);
    Frame request = replyFrame("NF000003");
    request.lead = '?';  // an echo of our own request
    QCOMPARE(matchReply(nf, request).kind, ReplyMatch::Unrelated);
}

void TestCommandCodec::wrongDataIsMalformed() {
    const CommandSpec& nf = spec('?', "NF");
    QCOMPARE(matchReply(nf, replyFrame("NF0000000A0000001401")).kind, ReplyMatch::Matches);
    const ReplyMatch shortReply = matchReply(nf, replyFrame("NF0000000A00000014"));
    QCOMPARE(shortReply.kind, ReplyMatch::Malformed);
    QVERIFY2(shortReply.detail.contains("more"), qPrintable(shortReply.detail));
    const ReplyMatch notHex = matchReply(nf, replyFrame("NF0000000A0000G01401"));
    QCOMPARE(notHex.kind, ReplyMatch::Malformed);
    QVERIFY2(notHex.detail.contains("off"), qPrintable(notHex.detail));
    QCOMPARE(matchReply(nf, replyFrame("NF0000000A000000140100")).kind, ReplyMatch::Malformed);
    QCOMPARE(matchReply(spec('?', "ATAB"), replyFrame("ATABF")).kind, ReplyMatch::Malformed);
    QCOMPARE(matchReply(spec('?', "ANTAB"), replyFrame("ANTAB12345")).kind, ReplyMatch::Malformed);
}

void TestCommandCodec::okReplyMustSayOkUnlessOptional() {
    QCOMPARE(matchReply(spec('!', "AMAX"), replyFrame("AMAXOK")).kind, ReplyMatch::Matches);
    QCOMPARE(matchReply(spec('!', "AMAX"), replyFrame("AMAX")).kind, ReplyMatch::Malformed);
    QCOMPARE(matchReply(spec('!', "AMAX"), replyFrame("AMAXNO")).kind, ReplyMatch::Malformed);
    QCOMPARE(matchReply(spec('!', "GTZKANZ"), replyFrame("GTZKANZ")).kind, ReplyMatch::Matches);
    QCOMPARE(matchReply(spec('!', "GTZKANZ"), replyFrame("GTZKANZOK")).kind, ReplyMatch::Matches);
}

void TestCommandCodec::replyAliasIsAccepted() {
    const ReplyMatch printed = matchReply(spec('?', "MEES"), replyFrame("MSE0000ABCD"));
    QCOMPARE(printed.kind, ReplyMatch::Matches);
    QCOMPARE(printed.fields.num("value"), 0xABCD);
    QCOMPARE(matchReply(spec('?', "MEES"), replyFrame("MEES0000ABCD")).fields.num("value"), 0xABCD);
    // "MPE" prefixes "MPEE": a value starting with E must still decode.
    QCOMPARE(matchReply(spec('?', "MPEE"), replyFrame("MPEE0001234")).fields.num("value"),
             0xE0001234);
    QCOMPARE(matchReply(spec('?', "MPEE"), replyFrame("MPEEE0001234")).fields.num("value"),
             0xE0001234);
    QCOMPARE(matchReply(spec('?', "MPEE"), replyFrame("MPE12")).kind, ReplyMatch::Malformed);
}

void TestCommandCodec::silentCommandTreatsEveryReplyAsUnrelated() {
    QCOMPARE(matchReply(spec('!', "GRESET"), replyFrame("GRESETOK")).kind, ReplyMatch::Unrelated);
}

void TestCommandCodec::signedFieldsAreSignExtended() {
    const QList<FieldSpec> specs{{"a", FieldType::SignedHex, 8},
                                 {"b", FieldType::SignedHex, 4},
                                 {"c", FieldType::Hex, 4},
                                 {"d", FieldType::SignedHex, 8}};
    const Result<Fields> fields = decodeFields(specs, "FFFFFFFF8000FFFF80000000");
    QVERIFY(fields.ok());
    QCOMPARE(fields->num("a"), -1);
    QCOMPARE(fields->num("b"), -32768);
    QCOMPARE(fields->num("c"), 65535);
    QCOMPARE(fields->num("d"), qint64(std::numeric_limits<qint32>::min()));
    QCOMPARE(encodeFields(specs, *fields).value(), QByteArray("FFFFFFFF8000FFFF80000000"));
}

void TestCommandCodec::decodeAcceptsLowerCaseHex() {
    const Result<Fields> fields = decodeFields({{"v", FieldType::Hex, 4}}, "abcd");
    QVERIFY(fields.ok());
    QCOMPARE(fields->num("v"), 0xABCD);
}

void TestCommandCodec::decodeRejectsTrailingData() {
    const Result<Fields> fields = decodeFields({{"v", FieldType::Hex, 2}}, "0102");
    QVERIFY(!fields.ok());
    QCOMPARE(fields.error().kind, ErrorKind::Communication);
    QVERIFY(!decodeFields({}, "x").ok());
    QVERIFY(decodeFields({}, "").ok());
}

void TestCommandCodec::textsLoseTheirNulPadding() {
    const Result<Fields> fields =
        decodeFields({{"t", FieldType::Text, 10}}, QByteArray("#.##\0\0\0\0\0\0", 10));
    QVERIFY(fields.ok());
    QCOMPARE(fields->bytes("t"), QByteArray("#.##"));
    Fields text;
    text.setBytes("t", "#.##");
    QCOMPARE(encodeFields({{"t", FieldType::Text, 10}}, text).value(),
             QByteArray("#.##\0\0\0\0\0\0", 10));
}

void TestCommandCodec::valueOutsideWidthIsInvalidDataNamingTheField_data() {
    QTest::addColumn<QByteArray>("command");
    QTest::addColumn<Fields>("fields");
    QTest::addColumn<QString>("field");
    QTest::newRow("program too big")
        << QByteArray("?NF") << Fields{{"program", 0x10000}} << "program";
    QTest::newRow("negative output") << QByteArray("?NF") << Fields{{"output", -1}} << "output";
    QTest::newRow("cam point above int32")
        << QByteArray("!NINS") << Fields{{"on", qint64(0x80000000LL)}} << "on";
    QTest::newRow("cam point below int32")
        << QByteArray("!NINS") << Fields{{"off", qint64(-0x80000001LL)}} << "off";
    QTest::newRow("offset word") << QByteArray("!AMODE") << Fields{{"offset", 40000}} << "offset";
    QTest::newRow("dead time negative") << QByteArray("!TZK") << Fields{{"value", -1}} << "value";
    QTest::newRow("not a number") << QByteArray("!PAU") << Fields{{"value", QByteArray("abc")}}
                                  << "value";
    Fields longText;
    longText.setBytes("text", "1234567890");
    QTest::newRow("format too long") << QByteArray("!IFOR") << longText << "text";
    Fields nul;
    nul.setBytes("text", QByteArray("ab\0c", 4));
    QTest::newRow("text with NUL") << QByteArray("!IFOR") << nul << "text";
    Fields access;
    access.setBytes("access", QByteArray(31, '\xff'));
    QTest::newRow("access bytes") << QByteArray("!USER") << access << "access";
    Fields symbols;
    symbols.setWords("symbols", QList<qint64>(29, 0));
    QTest::newRow("symbol count") << QByteArray("!GMXSPS") << symbols << "symbols";
    Fields symbolValue;
    symbolValue.setWords("symbols", QList<qint64>(30, 0x10000));
    QTest::newRow("symbol word") << QByteArray("!GMXSPS") << symbolValue << "symbols";
}

void TestCommandCodec::valueOutsideWidthIsInvalidDataNamingTheField() {
    QFETCH(QByteArray, command);
    QFETCH(Fields, fields);
    QFETCH(QString, field);
    const Result<QByteArray> body =
        encodeRequestBody(spec(command[0], command.constData() + 1), fields);
    QVERIFY(!body.ok());
    QCOMPARE(body.error().kind, ErrorKind::InvalidData);
    QVERIFY2(body.error().message.contains(QLatin1Char('"') + field + QLatin1Char('"')),
             qPrintable(body.error().message));
    QVERIFY2(body.error().message.contains(QString::fromLatin1(command)),
             qPrintable(body.error().message));
}

void TestCommandCodec::missingValuesEncodeAsZeroOrEmpty() {
    QCOMPARE(encodeRequestBody(spec('?', "NF"), {}).value(), QByteArray("NF000000"));
    QCOMPARE(encodeRequestBody(spec('?', "NF"), {{"program", 3}, {"output", 0xD5}}).value(),
             QByteArray("NF0003D5"));
    QCOMPARE(encodeRequestBody(spec('!', "IFOR"), {}).value(),
             QByteArray("IFOR") + QByteArray(10, '\0'));
    QCOMPARE(encodeRequestBody(spec('!', "NINS"), {{"on", -1}, {"off", 359}}).value(),
             QByteArray("NINS000000FFFFFFFF00000167"));
}

void TestCommandCodec::requestOfWrongCommandIsRejected() {
    QVERIFY(!decodeRequestFields(spec('?', "NF"), "NL").ok());
    const Result<Fields> shortRequest = decodeRequestFields(spec('?', "NF"), "NF0001");
    QVERIFY(!shortRequest.ok());
    QVERIFY2(shortRequest.error().message.contains("output"),
             qPrintable(shortRequest.error().message));
}

void TestCommandCodec::deviceErrorTextsCoverManualList() {
    QVERIFY(deviceErrorText(-43).contains("block number order"));
    QVERIFY(deviceErrorText(-21).contains("EEPROM is full"));
    QVERIFY(deviceErrorText(-39).contains("EEPROM is full"));
    // Every number of manual 4.6.1 has its meaning; -1 is "unknown error"
    // there, which is no meaning: the text says so.
    for (qint32 code : {-10, -12, -20, -21, -30, -39, -40, -41, -42, -43, -44, -45, -46}) {
        QVERIFY2(manualExplains(code), qPrintable(QString::number(code)));
        QVERIFY2(!deviceErrorText(code).contains("no meaning"), qPrintable(QString::number(code)));
    }
    for (qint32 code : {-1, -2, -11, -47, 5}) QVERIFY(!manualExplains(code));
    QVERIFY(deviceErrorText(-1).contains(
        QLatin1String("The manual gives no meaning for error -1 (it lists it only as \"unknown "
                      "error\")")));
    QCOMPARE(deviceErrorText(-47),
             QStringLiteral("The manual gives no meaning for error -47. Note the number and the "
                            "command and ask the device's supplier."));
    QVERIFY(deviceErrorText(5).contains(QLatin1String("error 5.")));
}

QTEST_GUILESS_MAIN(TestCommandCodec)
#include "tst_command_codec.moc"
