#include "comm/camcon/table/frame_3964r.h"
#include "comm/camcon/table/link_3964r.h"
#include "comm/camcon/table/rk512.h"
#include "link_pair.h"

#include <QtTest>

using namespace cambench::comm::table;
using cambench::comm::table::test::LinkPair;

namespace {

QByteArray hex(const char* text) {
    return QByteArray::fromHex(text);
}

const QByteArray kStxByte(1, kStx);
const QByteArray kDleByte(1, kDle);
const QByteArray kNakByte(1, kNak);

int countOf(const QByteArray& bytes, char c) {
    return int(bytes.count(c));
}

// Feeds `bytes` one at a time, `gapMs` apart from `startMs`; collects everything.
Actions feedByteByByte(Link3964R& link, const QByteArray& bytes, qint64 startMs, qint64 gapMs) {
    Actions all;
    qint64 now = startMs;
    for (char c : bytes) {
        const Actions actions = link.feed(QByteArrayView(&c, 1), now);
        all.write += actions.write;
        all.received += actions.received;
        all.log += actions.log;
        now += gapMs;
    }
    return all;
}

}  // namespace

class TestLink3964R : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void encodesNotesVectors_data();
    void encodesNotesVectors();
    void receivesNotesVectors_data();
    void receivesNotesVectors();
    void bccLeavesOutStx();
    void doublesDleWhenSendingAndUndoublesWhenReceiving();
    void sendsTelegramWithDleAsNotesShow();
    void deviceReplyArrivesAsItsOwnTransfer();
    void retriesAfterNakUpToSixAttemptsThenFails();
    void succeedsOnALaterAttempt();
    void onlyUnreadRepeatsAfterNakButNotAfterALostAcknowledgement();
    void ackTimeoutAfterStxRetriesAndFails();
    void ackTimeoutAfterBlockCountsAsFailedAttempt();
    void answerOtherThanDleFailsTheAttempt();
    void receiverAnswersNakOnBadBcc();
    void receiverAnswersNakOnCharacterTimeout();
    void gapsJustBelowCharacterTimeoutAreFine();
    void receiverDrainsAfterDleWithBadFollower();
    void receiverBoundsBufferAndResynchronises();
    void receivesTelegramSplitByteByByte();
    void collisionPcWinsAndDeviceSendsAfterwards();
    void collisionLowSideDoesNotCountYieldAsAttempt();
    void sendWhileReceivingIsQueued();
    void sendHandlesNoDeadline();
    void secondSendIsRefusedWhileBusy();
    void refusesEmptyAndOversizedTelegrams();
    void ignoresStrayBytesWhenIdle();
    void lateAnswerDuringRetryPauseIsIgnored();
    void resetDropsEverything();
    void retriesThroughANoisyLine();
};

void TestLink3964R::encodesNotesVectors_data() {
    QTest::addColumn<QByteArray>("telegram");
    QTest::addColumn<QByteArray>("block");
    QTest::newRow("captured block") << hex("04000701C32CC079") << hex("04000701C32CC079100347");
    QTest::newRow("DLE in data, BCC 0x10 once") << hex("411042") << hex("41101042100310");
    QTest::newRow("RK512 read area 5 offset 10 7 words")
        << hex("00004544050A0007FFFF") << hex("00004544050A0007FFFF10031A");
    QTest::newRow("RK512 reply no error") << hex("00000000") << hex("00000000100313");
}

void TestLink3964R::encodesNotesVectors() {
    QFETCH(QByteArray, telegram);
    QFETCH(QByteArray, block);
    QCOMPARE(encodeBlock3964r(telegram).toHex(' '), block.toHex(' '));
    QCOMPARE(bcc3964r(block.first(block.size() - 1)), quint8(block.back()));
}

void TestLink3964R::receivesNotesVectors_data() {
    encodesNotesVectors_data();
}

void TestLink3964R::receivesNotesVectors() {
    QFETCH(QByteArray, telegram);
    QFETCH(QByteArray, block);
    for (Link3964R::Priority priority : {Link3964R::Priority::High, Link3964R::Priority::Low}) {
        Link3964R link(priority);
        const Actions start = link.feed(kStxByte, 0);
        QCOMPARE(start.write, kDleByte);
        const Actions end = link.feed(block, 5);
        QCOMPARE(end.write, kDleByte);
        QCOMPARE(end.received, QList<QByteArray>{telegram});
        QVERIFY(link.idle());
    }
}

void TestLink3964R::bccLeavesOutStx() {
    // The captured block with the STX XORed into its BCC (0x47 ^ 0x02).
    Link3964R link(Link3964R::Priority::High);
    link.feed(kStxByte, 0);
    const Actions actions = link.feed(hex("04000701C32CC079100345"), 1);
    QCOMPARE(actions.write, kNakByte);
    QVERIFY(actions.received.isEmpty());
    QVERIFY2(actions.log.join('\n').contains("BCC"), qPrintable(actions.log.join('\n')));
}

void TestLink3964R::doublesDleWhenSendingAndUndoublesWhenReceiving() {
    const QByteArray telegram = hex("10101000FF10");
    const QByteArray block = encodeBlock3964r(telegram);
    QCOMPARE(block.first(block.size() - 3), hex("101010101010 00FF1010"));
    // Doubled DLEs cancel out in the XOR; the BCC is the XOR of the rest.
    QCOMPARE(quint8(block.back()), quint8(0x00 ^ 0xFF ^ 0x10 ^ 0x03));

    Link3964R receiver(Link3964R::Priority::Low);
    receiver.feed(kStxByte, 0);
    const Actions actions = receiver.feed(block, 1);
    QCOMPARE(actions.received, QList<QByteArray>{telegram});
}

void TestLink3964R::sendsTelegramWithDleAsNotesShow() {
    LinkPair pair;
    pair.send(pair.pc, hex("411042"));
    pair.run();
    QCOMPARE(pair.pc.sendDone, 1);
    QCOMPARE(pair.device.received, QList<QByteArray>{hex("411042")});
    QCOMPARE(pair.transcript,
             (QStringList{"pc>02", "dev>10", "pc>41 10 10 42 10 03 10", "dev>10"}));
    QVERIFY(pair.pc.link.idle());
    QVERIFY(pair.device.link.idle());
}

void TestLink3964R::deviceReplyArrivesAsItsOwnTransfer() {
    // PC sends the RK512 read of notes 7; the device answers with its own
    // 3964R transfer, which the PC acknowledges with DLE.
    LinkPair pair;
    const QByteArray request = hex("00004544050A0007FFFF");
    pair.send(pair.pc, request);
    pair.run();
    QCOMPARE(pair.device.received, QList<QByteArray>{request});
    pair.send(pair.device, hex("00000000"));
    pair.run();
    QCOMPARE(pair.pc.received, QList<QByteArray>{hex("00000000")});
    QCOMPARE(pair.transcript,
             (QStringList{"pc>02", "dev>10", "pc>00 00 45 44 05 0a 00 07 ff ff 10 03 1a", "dev>10",
                          "dev>02", "pc>10", "dev>00 00 00 00 10 03 13", "pc>10"}));
    QCOMPARE(pair.pc.sendDone, 1);
    QCOMPARE(pair.device.sendDone, 1);
}

void TestLink3964R::retriesAfterNakUpToSixAttemptsThenFails() {
    Link3964R pc(Link3964R::Priority::High);
    const QByteArray telegram = hex("00004544050A0007FFFF");
    qint64 now = 0;
    Actions actions = pc.send(telegram, now);
    QCOMPARE(actions.write, kStxByte);
    QByteArray wrote = actions.write;
    std::optional<QString> failed;
    for (int attempt = 1; attempt <= 6; ++attempt) {
        now += 10;
        actions = pc.feed(kDleByte, now);
        QCOMPARE(actions.write, encodeBlock3964r(telegram));
        now += 10;
        actions = pc.feed(kNakByte, now);
        QVERIFY(actions.write.isEmpty());
        QVERIFY(!actions.sendDone);
        if (attempt < 6) {
            QVERIFY(!actions.sendFailed);
            QCOMPARE(pc.nextDeadlineMs(), now + 220);  // quiet pause before the retry
            QVERIFY(pc.poll(now + 219).write.isEmpty());
            now += 220;
            actions = pc.poll(now);
            QCOMPARE(actions.write, kStxByte);
            QVERIFY2(
                actions.log.join('\n').contains(QStringLiteral("attempt %1 of 6").arg(attempt + 1)),
                qPrintable(actions.log.join('\n')));
            wrote += actions.write;
        } else {
            failed = actions.sendFailed;
        }
    }
    QCOMPARE(countOf(wrote, kStx), 6);
    QVERIFY(failed.has_value());
    QVERIFY2(failed->contains("6 attempts") && failed->contains("NAK"), qPrintable(*failed));
    QVERIFY(pc.idle());
    QCOMPARE(pc.nextDeadlineMs(), -1);
}

void TestLink3964R::succeedsOnALaterAttempt() {
    LinkPair pair;
    // The device's first two acknowledgements of the block turn into NAKs.
    // Its DLEs alternate: answer to STX, acknowledgement of the block.
    int deviceDles = 0;
    pair.device.filter = [&](const QByteArray& bytes) {
        if (bytes != kDleByte) return bytes;
        ++deviceDles;
        const bool blockAck = deviceDles % 2 == 0;
        return blockAck && deviceDles <= 4 ? kNakByte : bytes;
    };
    pair.send(pair.pc, hex("0A0B"));  // no 0x02 in the block: STX count = attempts
    pair.run();
    QCOMPARE(pair.pc.sendDone, 1);
    QVERIFY(pair.pc.sendFailed.isEmpty());
    QCOMPARE(countOf(pair.pc.wrote, kStx), 3);
    // The device received the telegram three times: 3964R has no sequence
    // numbers, so a lost acknowledgement means a repeat.
    QCOMPARE(pair.device.received.size(), 3);
}

void TestLink3964R::onlyUnreadRepeatsAfterNakButNotAfterALostAcknowledgement() {
    // A NAK after the block: the device found it bad and did not act on it.
    {
        Link3964R pc(Link3964R::Priority::High);
        pc.send(hex("0102"), 0, Link3964R::Repeat::OnlyUnread);
        pc.feed(kDleByte, 1);
        Actions actions = pc.feed(kNakByte, 2);
        QVERIFY(!actions.sendFailed);
        QCOMPARE(pc.poll(2 + 220).write, kStxByte);
    }
    // No DLE after the block: the device may have executed it.
    {
        Link3964R pc(Link3964R::Priority::High);
        pc.send(hex("0102"), 0, Link3964R::Repeat::OnlyUnread);
        pc.feed(kDleByte, 1);
        const Actions actions = pc.poll(2001);
        QVERIFY(actions.sendFailed.has_value());
        QVERIFY2(actions.sendFailed->contains("may have executed"),
                 qPrintable(*actions.sendFailed));
        QVERIFY(actions.write.isEmpty());
        QVERIFY(!pc.sending());
        QCOMPARE(pc.nextDeadlineMs(), -1);
    }
}

void TestLink3964R::ackTimeoutAfterStxRetriesAndFails() {
    Link3964R pc(Link3964R::Priority::High);
    pc.send(hex("0102"), 0);
    QCOMPARE(pc.nextDeadlineMs(), 2000);
    QVERIFY(pc.poll(1999).write.isEmpty());
    qint64 now = 0;
    int stx = 1;
    std::optional<QString> failed;
    for (int guard = 0; guard < 20 && !failed; ++guard) {
        now = pc.nextDeadlineMs();
        QVERIFY(now >= 0);
        const Actions actions = pc.poll(now);
        stx += countOf(actions.write, kStx);
        failed = actions.sendFailed;
    }
    QCOMPARE(stx, 6);
    QVERIFY(failed.has_value());
    QVERIFY2(failed->contains("no DLE within 2000 ms after STX"), qPrintable(*failed));
    // Six waits of 2 s and five pauses of 220 ms.
    QCOMPARE(now, 6 * 2000 + 5 * 220);
}

void TestLink3964R::ackTimeoutAfterBlockCountsAsFailedAttempt() {
    Link3964R pc(Link3964R::Priority::High, {2000, 220, 2});
    pc.send(hex("0102"), 0);
    pc.feed(kDleByte, 100);
    QCOMPARE(pc.nextDeadlineMs(), 2100);
    Actions actions = pc.poll(2100);
    QVERIFY2(actions.log.join('\n').contains("no DLE within 2000 ms after the block"),
             qPrintable(actions.log.join('\n')));
    QCOMPARE(pc.poll(2320).write, kStxByte);
    pc.feed(kDleByte, 2330);
    actions = pc.poll(4330);
    QVERIFY(actions.sendFailed.has_value());
    QVERIFY(actions.sendFailed->contains("2 attempts"));
}

void TestLink3964R::answerOtherThanDleFailsTheAttempt() {
    Link3964R pc(Link3964R::Priority::High);
    pc.send(hex("0102"), 0);
    const Actions actions = pc.feed(hex("41"), 5);
    QVERIFY2(actions.log.join('\n').contains("0x41 instead of DLE after STX"),
             qPrintable(actions.log.join('\n')));
    QCOMPARE(pc.nextDeadlineMs(), 5 + 220);
    QCOMPARE(pc.poll(225).write, kStxByte);
}

void TestLink3964R::receiverAnswersNakOnBadBcc() {
    Link3964R device(Link3964R::Priority::Low);
    device.feed(kStxByte, 0);
    QByteArray block = encodeBlock3964r(hex("0102"));
    block.back() = char(block.back() ^ 0x01);
    Actions actions = device.feed(block, 1);
    QCOMPARE(actions.write, kNakByte);
    QVERIFY(actions.received.isEmpty());
    QVERIFY(device.idle());
    // The sender's repeat goes through.
    QCOMPARE(device.feed(kStxByte, 300).write, kDleByte);
    actions = device.feed(encodeBlock3964r(hex("0102")), 301);
    QCOMPARE(actions.write, kDleByte);
    QCOMPARE(actions.received, QList<QByteArray>{hex("0102")});
}

void TestLink3964R::receiverAnswersNakOnCharacterTimeout() {
    Link3964R device(Link3964R::Priority::Low);
    device.feed(kStxByte, 0);
    device.feed(hex("4142"), 100);
    QCOMPARE(device.nextDeadlineMs(), 320);
    QVERIFY(device.poll(319).write.isEmpty());
    const Actions actions = device.poll(320);
    QCOMPARE(actions.write, kNakByte);
    QVERIFY2(actions.log.join('\n').contains("character delay"),
             qPrintable(actions.log.join('\n')));
    QVERIFY(device.idle());
    QCOMPARE(device.bufferedBytes(), 0);
    // Also while waiting for the BCC.
    device.feed(kStxByte, 1000);
    device.feed(hex("411003"), 1001);
    QCOMPARE(device.poll(1221).write, kNakByte);
}

void TestLink3964R::gapsJustBelowCharacterTimeoutAreFine() {
    Link3964R device(Link3964R::Priority::Low);
    const QByteArray telegram = hex("0010FF");
    const Actions actions = feedByteByByte(device, kStxByte + encodeBlock3964r(telegram), 0, 219);
    QCOMPARE(actions.received, QList<QByteArray>{telegram});
    QCOMPARE(actions.write, kDleByte + kDleByte);
}

void TestLink3964R::receiverDrainsAfterDleWithBadFollower() {
    Link3964R device(Link3964R::Priority::Low);
    device.feed(kStxByte, 0);
    // DLE 0x02 is no valid pair; the STX-looking rest must not start a transfer.
    Actions actions = device.feed(hex("411002"), 10);
    QVERIFY(actions.write.isEmpty());
    actions = device.feed(hex("02 42 10 03 00"), 100);
    QVERIFY(actions.write.isEmpty());
    QCOMPARE(device.nextDeadlineMs(), 320);
    actions = device.poll(320);
    QCOMPARE(actions.write, kNakByte);
    QVERIFY2(actions.log.join('\n').contains("DLE followed by STX"),
             qPrintable(actions.log.join('\n')));
    QVERIFY(device.idle());
}

void TestLink3964R::receiverBoundsBufferAndResynchronises() {
    Link3964R device(Link3964R::Priority::Low);
    device.feed(kStxByte, 0);
    const QByteArray tooLong(Link3964R::kMaxTelegramBytes + 50, 'A');
    Actions actions = device.feed(tooLong, 10);
    QVERIFY(actions.write.isEmpty());
    QVERIFY(device.bufferedBytes() <= Link3964R::kMaxTelegramBytes);
    actions = device.feed(encodeBlock3964r({}).last(3), 20);  // DLE ETX BCC of the long block
    QVERIFY(actions.received.isEmpty());
    actions = device.poll(240);
    QCOMPARE(actions.write, kNakByte);
    QVERIFY2(actions.log.join('\n').contains("longer than 600"),
             qPrintable(actions.log.join('\n')));

    // Exactly the maximum is accepted.
    const QByteArray longest(Link3964R::kMaxTelegramBytes, '\x10');
    QCOMPARE(device.feed(kStxByte, 1000).write, kDleByte);
    actions = device.feed(encodeBlock3964r(longest), 1001);
    QCOMPARE(actions.received, QList<QByteArray>{longest});
}

void TestLink3964R::receivesTelegramSplitByteByByte() {
    LinkPair pair;
    const QByteArray telegram = hex("00004144 0A00 0004 FFFF 10 10 03 02 15 10");
    // Every byte delivered on its own, 5 ms apart.
    Link3964R device(Link3964R::Priority::Low);
    Actions first = device.feed(kStxByte, 0);
    QCOMPARE(first.write, kDleByte);
    const Actions actions = feedByteByByte(device, encodeBlock3964r(telegram), 5, 5);
    QCOMPARE(actions.received, QList<QByteArray>{telegram});
    QCOMPARE(actions.write, kDleByte);
    QVERIFY(device.idle());
}

void TestLink3964R::collisionPcWinsAndDeviceSendsAfterwards() {
    LinkPair pair;
    const QByteArray request = hex("00004544C9000004FFFF");
    const QByteArray unsolicited = hex("3A0110");
    // Both start at the same instant.
    pair.send(pair.pc, request);
    pair.send(pair.device, unsolicited);
    QCOMPARE(pair.pc.inFlight, kStxByte);
    QCOMPARE(pair.device.inFlight, kStxByte);
    pair.run();
    QCOMPARE(pair.pc.sendDone, 1);
    QCOMPARE(pair.device.sendDone, 1);
    QVERIFY(pair.pc.sendFailed.isEmpty());
    QVERIFY(pair.device.sendFailed.isEmpty());
    QCOMPARE(pair.device.received, QList<QByteArray>{request});
    QCOMPARE(pair.pc.received, QList<QByteArray>{unsolicited});
    // The PC never answered the device's first STX; the device yielded with DLE.
    QCOMPARE(pair.transcript.first(4),
             (QStringList{"pc>02", "dev>02 10",
                          "pc>" + QString::fromLatin1(encodeBlock3964r(request).toHex(' ')),
                          "dev>10 02"}));
    QCOMPARE(countOf(pair.pc.wrote, kStx), 1);
    QCOMPARE(countOf(pair.device.wrote, kStx), 2);
    QVERIFY(pair.pc.link.idle());
    QVERIFY(pair.device.link.idle());
    QCOMPARE(pair.now, 0);  // no timeout was needed
}

void TestLink3964R::collisionLowSideDoesNotCountYieldAsAttempt() {
    Link3964R device(Link3964R::Priority::Low, {2000, 220, 1});
    device.send(hex("0102"), 0);
    Actions actions = device.feed(kStxByte, 1);
    QCOMPARE(actions.write, kDleByte);
    QVERIFY(!actions.sendFailed);
    actions = device.feed(encodeBlock3964r(hex("AA")), 2);
    QCOMPARE(actions.received, QList<QByteArray>{hex("AA")});
    // DLE for the received block, then its own single attempt starts.
    QCOMPARE(actions.write, kDleByte + kStxByte);
    QVERIFY2(actions.log.join('\n').contains("attempt 1 of 1"), qPrintable(actions.log.join('\n')));
    actions = device.feed(kDleByte, 3);
    actions = device.feed(kDleByte, 4);
    QVERIFY(actions.sendDone);
}

void TestLink3964R::sendWhileReceivingIsQueued() {
    Link3964R pc(Link3964R::Priority::High);
    QCOMPARE(pc.feed(kStxByte, 0).write, kDleByte);
    Actions actions = pc.send(hex("0102"), 1);
    QVERIFY(actions.write.isEmpty());
    QVERIFY(!actions.sendFailed);
    QVERIFY(pc.sending());
    actions = pc.feed(encodeBlock3964r(hex("3A01")), 2);
    QCOMPARE(actions.received, QList<QByteArray>{hex("3A01")});
    QCOMPARE(actions.write, kDleByte + kStxByte);
}

void TestLink3964R::sendHandlesNoDeadline() {
    // The incoming block's character delay has run out when send() comes:
    // send() only queues, and the next poll() answers NAK and starts the send.
    Link3964R pc(Link3964R::Priority::High);
    pc.feed(kStxByte, 0);
    pc.feed(hex("41"), 1);
    Actions actions = pc.send(hex("0102"), 500);
    QVERIFY(actions.write.isEmpty());
    QVERIFY(!actions.sendFailed);
    actions = pc.poll(500);
    QCOMPARE(actions.write, kNakByte + kStxByte);
}

void TestLink3964R::secondSendIsRefusedWhileBusy() {
    Link3964R pc(Link3964R::Priority::High);
    pc.send(hex("01"), 0);
    const Actions actions = pc.send(hex("02"), 1);
    QVERIFY(actions.sendFailed.has_value());
    QVERIFY(actions.write.isEmpty());
    // The first transfer goes on.
    QCOMPARE(pc.feed(kDleByte, 2).write, encodeBlock3964r(hex("01")));
    QVERIFY(pc.feed(kDleByte, 3).sendDone);
}

void TestLink3964R::refusesEmptyAndOversizedTelegrams() {
    Link3964R pc(Link3964R::Priority::High);
    QVERIFY(pc.send({}, 0).sendFailed.has_value());
    QVERIFY(pc.send(QByteArray(Link3964R::kMaxTelegramBytes + 1, 'x'), 0).sendFailed.has_value());
    QVERIFY(pc.idle());
    QCOMPARE(pc.send(QByteArray(Link3964R::kMaxTelegramBytes, 'x'), 0).write, kStxByte);
}

void TestLink3964R::ignoresStrayBytesWhenIdle() {
    Link3964R pc(Link3964R::Priority::High);
    const Actions actions = pc.feed(hex("10 15 03 41"), 0);
    QVERIFY(actions.write.isEmpty());
    QCOMPARE(actions.log.size(), 4);
    QVERIFY(pc.idle());
    QCOMPARE(pc.nextDeadlineMs(), -1);
}

void TestLink3964R::lateAnswerDuringRetryPauseIsIgnored() {
    Link3964R pc(Link3964R::Priority::High);
    pc.send(hex("01"), 0);
    pc.poll(2000);  // no DLE: first attempt failed, pause until 2220
    // The partner's DLE to the old STX arrives late; it must not count for
    // the next attempt, which has not started yet.
    Actions actions = pc.feed(kDleByte, 2100);
    QVERIFY(actions.write.isEmpty());
    actions = pc.poll(2220);
    QCOMPARE(actions.write, kStxByte);
    QCOMPARE(pc.feed(kDleByte, 2230).write, encodeBlock3964r(hex("01")));
}

void TestLink3964R::resetDropsEverything() {
    Link3964R pc(Link3964R::Priority::High);
    pc.feed(kStxByte, 0);
    pc.feed(hex("4142"), 1);
    pc.send(hex("01"), 2);
    QVERIFY(!pc.idle());
    pc.reset();
    QVERIFY(pc.idle());
    QCOMPARE(pc.bufferedBytes(), 0);
    QCOMPARE(pc.nextDeadlineMs(), -1);
}

void TestLink3964R::retriesThroughANoisyLine() {
    // Every third chunk from the PC loses its last byte: transfers must still
    // complete, each telegram at least once, within the six attempts.
    LinkPair pair;
    int chunk = 0;
    pair.pc.filter = [&](const QByteArray& bytes) {
        return (++chunk % 3 == 0 && bytes.size() > 1) ? bytes.chopped(1) : bytes;
    };
    for (int i = 0; i < 10; ++i) {
        const QByteArray telegram = hex("0000454405") + QByteArray(1, char(i)) + hex("0002FFFF");
        pair.send(pair.pc, telegram);
        pair.run(pair.now + 60'000);
        QCOMPARE(pair.pc.sendDone, i + 1);
        QVERIFY(pair.device.received.contains(telegram));
    }
    QVERIFY(pair.pc.sendFailed.isEmpty());
}

QTEST_GUILESS_MAIN(TestLink3964R)
#include "tst_link_3964r.moc"
