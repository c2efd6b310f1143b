#include "comm/camcon/ascii/frame.h"

#include <QtTest>

using namespace cambench::comm;

class TestFrame : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void manualVectorsEncodeByteExact_data();
    void manualVectorsEncodeByteExact();
    void checksumOfManualExampleIs4C();
    void checksumTextIsTwoUpperCaseDigits();
    void escapeBodyPrefixesCrAndEscOnly();
    void checksumExcludesEscapeBytes();
    void frameWithoutChecksumEndsDirectlyWithCrLf();
    void multiuserHeaderPrecedesLeadAndIsNotInChecksum_data();
    void multiuserHeaderPrecedesLeadAndIsNotInChecksum();
};

void TestFrame::manualVectorsEncodeByteExact_data() {
    QTest::addColumn<char>("lead");
    QTest::addColumn<QByteArray>("body");
    QTest::addColumn<QByteArray>("wire");
    // notes 1: every vector verified by hand.
    QTest::newRow("?IFGWG") << '?' << QByteArray("IFGWG") << QByteArray("?IFGWG4C\r\n");
    QTest::newRow(":IFOROK") << ':' << QByteArray("IFOROK") << QByteArray(":IFOROKFB\r\n");
    QTest::newRow(":EEOK") << ':' << QByteArray("EEOK") << QByteArray(":EEOKA1\r\n");
    QTest::newRow(":EEFFFF") << ':' << QByteArray("EEFFFF") << QByteArray(":EEFFFF23\r\n");
    QTest::newRow("?EE0001") << '?' << QByteArray("EE0001") << QByteArray("?EE000175\r\n");
    QTest::newRow("!EE0005") << '!' << QByteArray("EE0005") << QByteArray("!EE00058F\r\n");
    QTest::newRow(":EEERR-43") << ':' << QByteArray("EEERRFFFFFFD5")
                               << QByteArray(":EEERRFFFFFFD535\r\n");
}

void TestFrame::manualVectorsEncodeByteExact() {
    QFETCH(char, lead);
    QFETCH(QByteArray, body);
    QFETCH(QByteArray, wire);
    Frame frame;
    frame.lead = lead;
    frame.body = body;
    QCOMPARE(encodeFrame(frame), wire);
}

void TestFrame::checksumOfManualExampleIs4C() {
    // Manual 4.3: sum of "?IFGWG" is B3h, inverted 4Ch.
    QCOMPARE(checksum('?', "IFGWG"), quint8(0x4C));
}

void TestFrame::checksumTextIsTwoUpperCaseDigits() {
    QCOMPARE(checksumText(0x00), QByteArray("00"));
    QCOMPARE(checksumText(0x0A), QByteArray("0A"));
    QCOMPARE(checksumText(0xFB), QByteArray("FB"));
}

void TestFrame::escapeBodyPrefixesCrAndEscOnly() {
    const QByteArray body(
        "A\rB\x1b"
        "C\nD",
        7);
    QCOMPARE(escapeBody(body), QByteArray("A\x1b\rB\x1b\x1b"
                                          "C\nD",
                                          9));
    QCOMPARE(escapeBody(""), QByteArray());
}

void TestFrame::checksumExcludesEscapeBytes() {
    const QByteArray data("\x20\r\x1b\x00\x0a", 5);
    Frame frame;
    frame.lead = '!';
    frame.body = QByteArray("EE0001") + data;
    const QByteArray wire = encodeFrame(frame);

    quint8 sum = '!';
    for (char c : frame.body) sum = quint8(sum + quint8(c));
    const QByteArray expectedChecksum = checksumText(quint8(~sum));
    QCOMPARE(wire, QByteArray("!EE0001\x20\x1b\r\x1b\x1b\x00\x0a", 14) + expectedChecksum + "\r\n");
}

void TestFrame::frameWithoutChecksumEndsDirectlyWithCrLf() {
    Frame frame;
    frame.lead = '!';
    frame.body = "C0";
    frame.hasChecksum = false;
    QCOMPARE(encodeFrame(frame), QByteArray("!C0\r\n"));
}

void TestFrame::multiuserHeaderPrecedesLeadAndIsNotInChecksum_data() {
    QTest::addColumn<int>("block");
    for (int block = 0; block < 64; ++block) QTest::addRow("block %d", block) << block;
}

void TestFrame::multiuserHeaderPrecedesLeadAndIsNotInChecksum() {
    QFETCH(int, block);
    Frame frame;
    frame.lead = '?';
    frame.body = "IFGWG";
    frame.address = MultiuserAddress{63, 5, block};
    const QByteArray wire = encodeFrame(frame);
    QCOMPARE(quint8(wire[0]), quint8(0x40 + 63));
    QCOMPARE(quint8(wire[1]), quint8(0x80 + 5));
    QCOMPARE(quint8(wire[2]), quint8(0xC0 + block));
    QCOMPARE(wire.mid(3), QByteArray("?IFGWG4C\r\n"));
}

QTEST_GUILESS_MAIN(TestFrame)
#include "tst_frame.moc"
