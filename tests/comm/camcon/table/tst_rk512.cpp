#include "comm/camcon/table/frame_3964r.h"
#include "comm/camcon/table/rk512.h"
#include "comm/camcon/table/rk512_planner.h"

#include <QtTest>

using namespace cambench;
using namespace cambench::comm::table;

namespace {

QByteArray hex(const char* text) {
    return QByteArray::fromHex(text);
}

Rk512Request readRequest(int area, int offset, int words16) {
    Rk512Request request;
    request.area = area;
    request.offset = offset;
    request.words16 = words16;
    return request;
}

}  // namespace

class TestRk512 : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void encodesNotesReadVector();
    void encodesWriteWithData();
    void decodesNotesReplyVector();
    void decodesReadReplyData();
    void reportsDeviceErrors_data();
    void reportsDeviceErrors();
    void rejectsMalformedReplies();
    void refusesBadRequestFields();
    void parsesRequestsOnDeviceSide();
    void deviceSideErrorNumbers_data();
    void deviceSideErrorNumbers();
    void describesVariants();
    void convertsTableWords();
    void plansN96RangeIntoTelegramsOf32Words();
    void plansE38WithOffsetsIn16BitWords();
    void refusesRangesOutsideTheVariant();
    void planTableWriteSlicesValues();
    void planReachesEveryWordExactlyOnce();
};

void TestRk512::encodesNotesReadVector() {
    const Result<QByteArray> telegram = encodeRk512Request(readRequest(5, 10, 7));
    QVERIFY(telegram.ok());
    QCOMPARE(telegram->toHex(' '), hex("00004544050A0007FFFF").toHex(' '));
    QCOMPARE(encodeBlock3964r(*telegram), hex("00004544050A0007FFFF10031A"));
}

void TestRk512::encodesWriteWithData() {
    Rk512Request request;
    request.order = Rk512Order::Write;
    request.area = 205;
    request.offset = 4;
    request.words16 = 2;
    request.data = tableWordsToBytes({1});
    const Result<QByteArray> telegram = encodeRk512Request(request);
    QVERIFY(telegram.ok());
    QCOMPARE(telegram->toHex(' '), hex("00004144CD040002FFFF00000001").toHex(' '));
}

void TestRk512::decodesNotesReplyVector() {
    Rk512Request write;
    write.order = Rk512Order::Write;
    write.words16 = 2;
    write.data = hex("00000000");
    const Result<QByteArray> data = decodeRk512Reply(hex("00000000"), write);
    QVERIFY2(data.ok(), qPrintable(data.error().message));
    QVERIFY(data->isEmpty());
    QCOMPARE(encodeRk512Reply(Rk512Error::None), hex("00000000"));
    QCOMPARE(encodeBlock3964r(encodeRk512Reply(Rk512Error::None)), hex("00000000100313"));
}

void TestRk512::decodesReadReplyData() {
    const Rk512Request request = readRequest(201, 0, 4);
    const QByteArray payload = tableWordsToBytes({1234, -5});
    const Result<QByteArray> data =
        decodeRk512Reply(encodeRk512Reply(Rk512Error::None, payload), request);
    QVERIFY(data.ok());
    QCOMPARE(*data, payload);
    QCOMPARE(*bytesToTableWords(*data), (QList<qint32>{1234, -5}));
}

void TestRk512::reportsDeviceErrors_data() {
    QTest::addColumn<int>("number");
    QTest::addColumn<QString>("meaning");
    QTest::addColumn<QString>("advice");
    QTest::newRow("16") << 16 << "only data blocks"
                        << "report this as a bug";
    QTest::newRow("20") << 20 << "beyond the data block"
                        << "Check the area and word numbers";
    QTest::newRow("22") << 22 << "only read ('E') and write ('A')"
                        << "report this as a bug";
    QTest::newRow("52") << 52 << "more than 128 bytes"
                        << "Split the transfer";
    QTest::newRow("54") << 54 << "general error"
                        << "Check the value";
    QTest::newRow("unlisted") << 99 << "not listed in the manual"
                              << "Check the request";
}

void TestRk512::reportsDeviceErrors() {
    QFETCH(int, number);
    QFETCH(QString, meaning);
    QFETCH(QString, advice);
    const Rk512Request request = readRequest(5, 10, 8);
    const Result<QByteArray> data = decodeRk512Reply(encodeRk512Reply(Rk512Error(number)), request);
    QVERIFY(!data.ok());
    QCOMPARE(data.error().kind, ErrorKind::DeviceError);
    QCOMPARE(data.error().deviceCode, number);
    const QString message = data.error().message;
    QVERIFY2(message.contains(meaning), qPrintable(message));
    QVERIFY2(message.contains(advice), qPrintable(message));
    QVERIFY2(message.contains("data area 5") && message.contains("offset 10"), qPrintable(message));
}

void TestRk512::rejectsMalformedReplies() {
    const Rk512Request request = readRequest(5, 10, 2);
    for (const QByteArray& reply : {hex(""), hex("000000"), hex("0100000000000000"), hex("3A01"),
                                    hex("00000000 0000"), hex("00000000 0000000000")}) {
        const Result<QByteArray> data = decodeRk512Reply(reply, request);
        QVERIFY2(!data.ok(), reply.toHex(' ').constData());
        QCOMPARE(data.error().kind, ErrorKind::Communication);
    }
    Rk512Request write = request;
    write.order = Rk512Order::Write;
    QCOMPARE(decodeRk512Reply(hex("0000000000"), write).error().kind, ErrorKind::Communication);
}

void TestRk512::refusesBadRequestFields() {
    QCOMPARE(encodeRk512Request(readRequest(0, 0, 2)).error().kind, ErrorKind::Usage);
    QCOMPARE(encodeRk512Request(readRequest(256, 0, 2)).error().kind, ErrorKind::Usage);
    QCOMPARE(encodeRk512Request(readRequest(5, 256, 2)).error().kind, ErrorKind::Usage);
    QCOMPARE(encodeRk512Request(readRequest(5, -1, 2)).error().kind, ErrorKind::Usage);
    QCOMPARE(encodeRk512Request(readRequest(5, 0, 1)).error().kind, ErrorKind::Usage);
    QCOMPARE(encodeRk512Request(readRequest(5, 0, 65)).error().kind, ErrorKind::Usage);
    QVERIFY(encodeRk512Request(readRequest(255, 255, 64)).ok());
    Rk512Request read = readRequest(5, 0, 2);
    read.data = hex("00000001");
    QCOMPARE(encodeRk512Request(read).error().kind, ErrorKind::Usage);  // a read carries no data
    Rk512Request write = readRequest(5, 0, 4);
    write.order = Rk512Order::Write;
    write.data = hex("00000001");
    const Result<QByteArray> tooShort = encodeRk512Request(write);
    QVERIFY(!tooShort.ok());
    QVERIFY2(tooShort.error().message.contains("4 data bytes, 8 expected"),
             qPrintable(tooShort.error().message));
}

void TestRk512::parsesRequestsOnDeviceSide() {
    const Rk512ParsedRequest read =
        parseRk512Request(hex("00004544050A0008FFFF"), Rk512Variant::N96);
    QCOMPARE(read.error, Rk512Error::None);
    QVERIFY(read.request.has_value());
    QCOMPARE(*read.request, readRequest(5, 10, 8));

    Rk512Request write = readRequest(203, 14, 2);
    write.order = Rk512Order::Write;
    write.data = tableWordsToBytes({-100});
    const Rk512ParsedRequest parsed =
        parseRk512Request(*encodeRk512Request(write), Rk512Variant::N96);
    QVERIFY(parsed.request.has_value());
    QCOMPARE(*parsed.request, write);

    // The notes' 7-word read is a whole request in e38, where a count need
    // not fill 32-bit table words.
    QCOMPARE(parseRk512Request(hex("00004544050A0007FFFF"), Rk512Variant::E38).error,
             Rk512Error::None);
}

void TestRk512::deviceSideErrorNumbers_data() {
    QTest::addColumn<QByteArray>("telegram");
    QTest::addColumn<int>("variant");
    QTest::addColumn<int>("error");
    const int n96 = int(Rk512Variant::N96);
    const int e38 = int(Rk512Variant::E38);
    QTest::newRow("block type M") << hex("0000454D05000002FFFF") << n96 << 16;
    QTest::newRow("order X") << hex("0000584405000002FFFF") << n96 << 22;
    QTest::newRow("65 words") << hex("0000454405000041FFFF") << n96 << 52;
    QTest::newRow("n96 past word 255") << hex("00004544 05FF0004 FFFF") << n96 << 20;
    QTest::newRow("n96 last word") << hex("00004544 05FF0002 FFFF") << n96 << 0;
    QTest::newRow("e38 past 16-bit word 255") << hex("00004544 05FF0002 FFFF") << e38 << 20;
    QTest::newRow("e38 last two 16-bit words") << hex("00004544 05FE0002 FFFF") << e38 << 0;
    QTest::newRow("n96 odd count") << hex("00004544050A0007FFFF") << n96 << 54;
    QTest::newRow("area 0") << hex("0000454400000002FFFF") << n96 << 54;
    QTest::newRow("1 word") << hex("0000454405000001FFFF") << n96 << 54;
    QTest::newRow("no coordination flag") << hex("00004544050A00020000") << n96 << 54;
    QTest::newRow("short header") << hex("00004544050A0002FF") << n96 << 54;
    QTest::newRow("not 00 00") << hex("01004544050A0002FFFF") << n96 << 54;
    QTest::newRow("write, data missing") << hex("00004144050A0002FFFF0000") << n96 << 54;
    QTest::newRow("write, data too long") << hex("00004144050A0002FFFF0000000000") << n96 << 52;
    QTest::newRow("read with data") << hex("00004544050A0002FFFF00") << n96 << 52;
}

void TestRk512::deviceSideErrorNumbers() {
    QFETCH(QByteArray, telegram);
    QFETCH(int, variant);
    QFETCH(int, error);
    const Rk512ParsedRequest parsed = parseRk512Request(telegram, Rk512Variant(variant));
    QCOMPARE(int(parsed.error), error);
    QCOMPARE(parsed.request.has_value(), error == 0);
    if (error != 0) QVERIFY(!parsed.detail.isEmpty());
}

void TestRk512::describesVariants() {
    const Rk512VariantInfo& n96 = rk512VariantInfo(Rk512Variant::N96);
    QCOMPARE(n96.baudRate, 9600);
    QCOMPARE(n96.parity, 'N');
    QCOMPARE(n96.offsetsPerWord, 1);
    QCOMPARE(n96.reachableWords, 256);
    QVERIFY(!n96.provisional);
    const Rk512VariantInfo& e38 = rk512VariantInfo(Rk512Variant::E38);
    QCOMPARE(e38.baudRate, 38400);
    QCOMPARE(e38.parity, 'E');
    QCOMPARE(e38.offsetsPerWord, 2);
    QCOMPARE(e38.reachableWords, 128);
    QVERIFY(e38.provisional && QByteArray(e38.provisional).startsWith("provisional"));
}

void TestRk512::convertsTableWords() {
    const QList<qint32> words{0, 1, -1, qint32(0x80000000u), 0x10203040};
    const QByteArray bytes = tableWordsToBytes(words);
    QCOMPARE(bytes.toHex(' '), hex("00000000 00000001 FFFFFFFF 80000000 10203040").toHex(' '));
    QCOMPARE(*bytesToTableWords(bytes), words);
    QCOMPARE(bytesToTableWords(hex("000000")).error().kind, ErrorKind::Communication);
}

void TestRk512::plansN96RangeIntoTelegramsOf32Words() {
    const Result<QList<TableChunk>> chunks = planTableTransfer(Rk512Variant::N96, 7, 0, 256);
    QVERIFY(chunks.ok());
    QCOMPARE(chunks->size(), 8);
    QCOMPARE(chunks->first(), (TableChunk{7, 0, 32}));
    QCOMPARE(chunks->last(), (TableChunk{7, 224, 32}));

    const Result<QList<Rk512Request>> reads = planTableRead(Rk512Variant::N96, 7, 0, 256);
    QVERIFY(reads.ok());
    for (const Rk512Request& request : *reads) {
        QCOMPARE(request.words16, 64);  // 128 data bytes
        QVERIFY(encodeRk512Request(request).ok());
        QCOMPARE(encodeRk512Request(request)->size(), kRk512RequestHeaderBytes);
    }
    QCOMPARE(reads->at(1).offset, 32);

    const Result<QList<TableChunk>> one = planTableTransfer(Rk512Variant::N96, 201, 34, 1);
    QCOMPARE(*one, (QList<TableChunk>{{201, 34, 1}}));
    QCOMPARE(readRequestFor(Rk512Variant::N96, one->first()).words16, 2);
    QCOMPARE(readRequestFor(Rk512Variant::N96, one->first()).offset, 34);
}

void TestRk512::plansE38WithOffsetsIn16BitWords() {
    const Result<QList<Rk512Request>> reads = planTableRead(Rk512Variant::E38, 5, 10, 40);
    QVERIFY(reads.ok());
    QCOMPARE(reads->size(), 2);
    QCOMPARE(reads->at(0).offset, 20);
    QCOMPARE(reads->at(0).words16, 64);
    QCOMPARE(reads->at(1).offset, 84);
    QCOMPARE(reads->at(1).words16, 16);
    // Every request the planner makes, the device side accepts.
    for (const Rk512Request& request : *reads) {
        QCOMPARE(parseRk512Request(*encodeRk512Request(request), Rk512Variant::E38).error,
                 Rk512Error::None);
    }
}

void TestRk512::refusesRangesOutsideTheVariant() {
    QVERIFY(planTableTransfer(Rk512Variant::N96, 5, 255, 1).ok());
    QCOMPARE(planTableTransfer(Rk512Variant::N96, 5, 255, 2).error().kind, ErrorKind::Usage);
    QCOMPARE(planTableTransfer(Rk512Variant::N96, 5, -1, 2).error().kind, ErrorKind::Usage);
    QCOMPARE(planTableTransfer(Rk512Variant::N96, 5, 0, 0).error().kind, ErrorKind::Usage);
    QCOMPARE(planTableTransfer(Rk512Variant::N96, 0, 0, 1).error().kind, ErrorKind::Usage);
    QCOMPARE(planTableTransfer(Rk512Variant::N96, 5, 0, 4, 33).error().kind, ErrorKind::Usage);
    QVERIFY(planTableTransfer(Rk512Variant::E38, 5, 127, 1).ok());
    const Result<QList<TableChunk>> e38 = planTableTransfer(Rk512Variant::E38, 1, 120, 20);
    QVERIFY(!e38.ok());
    QVERIFY2(e38.error().message.contains("3964R n96"), qPrintable(e38.error().message));
}

void TestRk512::planTableWriteSlicesValues() {
    QList<qint32> values;
    for (int i = 0; i < 70; ++i) values.append(1000 + i);
    const Result<QList<Rk512Request>> writes = planTableWrite(Rk512Variant::N96, 9, 1, values);
    QVERIFY(writes.ok());
    QCOMPARE(writes->size(), 3);
    QList<qint32> joined;
    for (const Rk512Request& request : *writes) {
        QCOMPARE(request.order, Rk512Order::Write);
        QCOMPARE(request.data.size(), request.words16 * 2);
        // Starts at word 1 with an even size: each telegram begins at a
        // cam's switch-on point.
        QCOMPARE(request.offset % 2, 1);
        joined += *bytesToTableWords(request.data);
    }
    QCOMPARE(joined, values);
    QCOMPARE(writes->at(2).offset, 65);
    QCOMPARE(writes->at(2).words16, 12);
}

void TestRk512::planReachesEveryWordExactlyOnce() {
    for (Rk512Variant variant : {Rk512Variant::N96, Rk512Variant::E38}) {
        const int reachable = rk512VariantInfo(variant).reachableWords;
        for (int first = 0; first < reachable; first += 7) {
            for (int count : {1, 2, 31, 32, 33, 64, 65}) {
                if (first + count > reachable) continue;
                const Result<QList<TableChunk>> chunks =
                    planTableTransfer(variant, 3, first, count);
                QVERIFY(chunks.ok());
                int next = first;
                for (const TableChunk& chunk : *chunks) {
                    QCOMPARE(chunk.firstWord, next);
                    QVERIFY(chunk.wordCount >= 1 && chunk.wordCount <= kMaxTableWordsPerTelegram);
                    next += chunk.wordCount;
                }
                QCOMPARE(next, first + count);
            }
        }
    }
}

QTEST_GUILESS_MAIN(TestRk512)
#include "tst_rk512.moc"
