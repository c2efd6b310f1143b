// Issue 16: Cam-BUS on the wire: docs/protocols/cambus.md's worked example byte for byte (the
// PC 63 asks CamCon 3 ?GNR and gets its reply), the block bit, damaged
// blocks, and the pseudo-terminal's encoding of breaks (P12).
#include "comm/camcon/cambus/cambus_block.h"

#include <QTest>

using namespace cambench;
using namespace cambench::comm;

class TestCamBusBlock : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void theWorkedExampleByteForByte() {
        QCOMPARE(camBusToken(63), QByteArray::fromHex("a5373f3f"));
        QCOMPARE(camBusToken(3), QByteArray::fromHex("a5370303"));
        QCOMPARE(camBusByte(CamBusByteKind::Nak, 63), quint8(0xBF));
        QCOMPARE(camBusByte(CamBusByteKind::Ack, 3), quint8(0x43));
        QCOMPARE(camBusByte(CamBusByteKind::Nak, 3), quint8(0x83));
        // The request: "?GNR" with its checksum characters "D9".
        const Result<QByteArray> request = encodeCamBusBlock({QByteArray("?GNRD9"), false});
        QVERIFY(request.ok());
        QCOMPARE(*request, QByteArray::fromHex("063f474e52443901a9"));
        // The reply: ":GNR037B".
        QByteArray reply = QByteArray::fromHex(
            "083a474e5230333742"
            "0205");
        const Result<std::optional<CamBusBlock>> taken = takeCamBusBlock(reply);
        QVERIFY(taken.ok() && taken->has_value());
        QCOMPARE((*taken)->data, QByteArray(":GNR037B"));
        QVERIFY(!(*taken)->blockBit);
        QVERIFY(reply.isEmpty());
    }

    void theBlockBitIsTheTopBitOfChk1() {
        const Result<QByteArray> one = encodeCamBusBlock({QByteArray("?GNRD9"), true});
        QCOMPARE(*one, QByteArray::fromHex("063f474e524439"
                                           "81a9"));
        QByteArray wire = *one;
        QVERIFY((*takeCamBusBlock(wire))->blockBit);
    }

    void damagedAndIncompleteBlocks() {
        QByteArray partial = QByteArray::fromHex("063f474e52");
        const Result<std::optional<CamBusBlock>> waiting = takeCamBusBlock(partial);
        QVERIFY(waiting.ok() && !waiting->has_value());
        QCOMPARE(partial.size(), 5);  // kept for the rest
        QByteArray bad = QByteArray::fromHex("063f474e52443901aa");
        QCOMPARE(takeCamBusBlock(bad).error().kind, ErrorKind::InvalidData);
        QByteArray zero = QByteArray::fromHex("00");
        QVERIFY(!takeCamBusBlock(zero).ok());
        QVERIFY(!encodeCamBusBlock({QByteArray(), false}).ok());
        QVERIFY(!encodeCamBusBlock({QByteArray(256, 'x'), false}).ok());
        // The sum keeps 15 bits: 255 bytes of 0xFF and LEN 0xFF.
        const Result<QByteArray> big = encodeCamBusBlock({QByteArray(255, '\xff'), false});
        QVERIFY(big.ok());
        QByteArray back = *big;
        QCOMPARE((*takeCamBusBlock(back))->data, QByteArray(255, '\xff'));
    }

    void breaksAndFfOnAPty() {
        QCOMPARE(escapeBreakMarks(QByteArray::fromHex("01ff02")), QByteArray::fromHex("01ffff02"));
        QByteArray pending = QByteArray::fromHex("41ffff42ff0000ff0000c0");
        const QList<MarkedRead> reads = takeBreakMarked(pending);
        QCOMPARE(reads.size(), 4);
        QCOMPARE(reads.at(0).kind, MarkedRead::Data);
        QCOMPARE(reads.at(0).data, QByteArray::fromHex("41ff42"));
        QCOMPARE(reads.at(1).kind, MarkedRead::Break);
        QCOMPARE(reads.at(2).kind, MarkedRead::Break);
        QCOMPARE(reads.at(3).data, QByteArray::fromHex("c0"));
        QVERIFY(pending.isEmpty());
        QByteArray split = QByteArray::fromHex("43ff");
        QCOMPARE(takeBreakMarked(split).first().data, QByteArray::fromHex("43"));
        QCOMPARE(split, QByteArray::fromHex("ff"));  // waits for its partner
        split += QByteArray::fromHex("0000");
        QCOMPARE(takeBreakMarked(split).first().kind, MarkedRead::Break);
    }
};

QTEST_GUILESS_MAIN(TestCamBusBlock)
#include "tst_cambus_block.moc"
