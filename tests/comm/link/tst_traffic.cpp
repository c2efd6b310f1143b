// The traffic log line and the masking of user numbers, on wire bytes.
#include "comm/camcon/ascii/command_codec.h"
#include "comm/camcon/ascii/traffic_mask.h"
#include "comm/traffic/traffic_log.h"

#include <QtTest>

using namespace cambench;
using namespace cambench::comm;

namespace {

QByteArray userReplyBody(const QByteArray& name, const QByteArray& number) {
    return encodeReplyBody(
               *findCommand('?', "USER"),
               Fields{{"name", name}, {"number", number}, {"access", QByteArray(32, '\0')}})
        .value();
}

}  // namespace

class TestTraffic : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void lineShowsTimeDirectionHexAndAscii();
    void incomingLineUsesLessThan();
    void userReplyNumberIsMasked();
    void userRequestNumbersAreMasked();
    void escapedByteInNumberIsMaskedWithItsEsc();
    void multiuserHeaderIsSkipped();
    void partialFrameIsMaskedAsFarAsItGoes();
    void otherFramesAreUnchanged();
};

void TestTraffic::lineShowsTimeDirectionHexAndAscii() {
    const TrafficEntry entry{QDateTime(QDate(2026, 11, 21), QTime(22, 41, 53, 123)), true,
                             QByteArray("?IFGWG4C\r\n")};
    QCOMPARE(
        formatTrafficEntry(entry),
        QStringLiteral("2026-11-21T22:41:53.123 > 3F 49 46 47 57 47 34 43 0D 0A  |?IFGWG4C..|"));
}

void TestTraffic::incomingLineUsesLessThan() {
    const TrafficEntry entry{QDateTime(QDate(2026, 1, 2), QTime(3, 4, 5, 6)), false,
                             QByteArray("\xC1:\x7F", 3)};
    QCOMPARE(formatTrafficEntry(entry),
             QStringLiteral("2026-01-02T03:04:05.006 < C1 3A 7F  |.:.|"));
}

void TestTraffic::userReplyNumberIsMasked() {
    const QByteArray wire =
        encodeFrame(Frame{':', userReplyBody("Meier", "4711"), std::nullopt, true});
    const QByteArray masked = maskSecrets(wire, false);
    QCOMPARE(masked.size(), wire.size());
    QVERIFY(!masked.contains("4711"));
    QCOMPARE(masked.mid(1 + 4 + 22, 6), QByteArray("******"));
    QVERIFY(masked.contains("Meier"));
    // Only the number changed.
    QCOMPARE(masked.left(27), wire.left(27));
    QCOMPARE(masked.mid(33), wire.mid(33));
    // An outgoing frame with the same bytes is not a ?USER reply.
    QCOMPARE(maskSecrets(wire, true), wire);
}

void TestTraffic::userRequestNumbersAreMasked() {
    const QByteArray body =
        encodeRequestBody(*findCommand('!', "USER"), Fields{{"oldNumber", QByteArray("1234")},
                                                            {"name", QByteArray("X")},
                                                            {"number", QByteArray("DEL")}})
            .value();
    const QByteArray wire = encodeFrame(Frame{'!', body, std::nullopt, true});
    const QByteArray masked = maskSecrets(wire, true);
    QCOMPARE(masked.mid(1 + 4, 6), QByteArray("******"));
    QCOMPARE(masked.mid(1 + 4 + 6 + 22, 6), QByteArray("******"));
    QVERIFY(!masked.contains("1234"));
    QVERIFY(!masked.contains("DEL"));
    QVERIFY(masked.endsWith("\r\n"));
}

void TestTraffic::escapedByteInNumberIsMaskedWithItsEsc() {
    const QByteArray wire =
        encodeFrame(Frame{':', userReplyBody("A", QByteArray("1\r2")), std::nullopt, true});
    QVERIFY(wire.contains(QByteArray("1\x1b\r2")));
    const QByteArray masked = maskSecrets(wire, false);
    QCOMPARE(masked.size(), wire.size());
    QCOMPARE(masked.mid(1 + 4 + 22, 7), QByteArray("*******"));
    QVERIFY(masked.endsWith("\r\n"));
}

void TestTraffic::multiuserHeaderIsSkipped() {
    const QByteArray wire =
        encodeFrame(Frame{':', userReplyBody("A", "999"), MultiuserAddress{5, 63, 7}, true});
    const QByteArray masked = maskSecrets(wire, false);
    QCOMPARE(masked.left(3), wire.left(3));
    QCOMPARE(masked.mid(3 + 1 + 4 + 22, 6), QByteArray("******"));
    QVERIFY(!masked.contains("999"));
}

void TestTraffic::partialFrameIsMaskedAsFarAsItGoes() {
    const QByteArray wire = encodeFrame(Frame{':', userReplyBody("A", "4711"), std::nullopt, true});
    const QByteArray part = wire.left(1 + 4 + 22 + 3);  // up to "471"
    const QByteArray masked = maskSecrets(part, false);
    QCOMPARE(masked.right(3), QByteArray("***"));
    QCOMPARE(masked.size(), part.size());
}

void TestTraffic::otherFramesAreUnchanged() {
    const QByteArray ok = encodeFrame(Frame{':', "USEROK", std::nullopt, true});
    QCOMPARE(maskSecrets(ok, false), ok);
    const QByteArray query = encodeFrame(Frame{'?', "USER00", std::nullopt, true});
    QCOMPARE(maskSecrets(query, true), query);
    const QByteArray nf = encodeFrame(Frame{':', "NF000000640000000C800", std::nullopt, true});
    QCOMPARE(maskSecrets(nf, false), nf);
    QCOMPARE(maskSecrets(QByteArray("garbage"), false), QByteArray("garbage"));
}

QTEST_GUILESS_MAIN(TestTraffic)
#include "tst_traffic.moc"
