#include "comm/camcon/ascii/stream_decoder.h"

#include <QtTest>

using namespace cambench::comm;

namespace {

Frame makeFrame(char lead, const QByteArray& body, std::optional<MultiuserAddress> address = {}) {
    Frame frame;
    frame.lead = lead;
    frame.body = body;
    frame.address = address;
    return frame;
}

QList<DecodeEvent::Kind> kinds(const QList<DecodeEvent>& events) {
    QList<DecodeEvent::Kind> out;
    for (const DecodeEvent& event : events) out.append(event.kind);
    return out;
}

QList<Frame> framesOf(const QList<DecodeEvent>& events) {
    QList<Frame> out;
    for (const DecodeEvent& event : events) {
        if (event.kind == DecodeEvent::FrameOk) out.append(event.frame);
    }
    return out;
}

QList<DecodeEvent> feedByteByByte(StreamDecoder& decoder, const QByteArray& bytes) {
    QList<DecodeEvent> events;
    for (char c : bytes) events.append(decoder.feed(QByteArrayView(&c, 1)));
    return events;
}

// Three frames of different kinds, including binary data that needs escapes.
QList<Frame> sampleFrames(bool multiuser) {
    auto address = [&](int block) -> std::optional<MultiuserAddress> {
        if (!multiuser) return std::nullopt;
        return MultiuserAddress{7, 63, block};
    };
    return {makeFrame(':', "IFOROK", address(0)),
            makeFrame(':', QByteArray("EE0001\x20\r\x1b\n\x00:?!\r\n", 15), address(1)),
            makeFrame(':', "EEFFFF", address(63))};
}

QByteArray wireOf(const QList<Frame>& frames) {
    QByteArray wire;
    for (const Frame& frame : frames) wire += encodeFrame(frame);
    return wire;
}

}  // namespace

class TestStreamDecoder : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void decodesManualVectors_data();
    void decodesManualVectors();
    void reportsWrongChecksum();
    void reportsMissingChecksum();
    void acceptsC0WithoutChecksumWhileChecksumsAreOn();
    void acceptsFramesWithoutChecksumWhenChecksumsAreOff();
    void unescapesBinaryDataWithCrAndEsc();
    void decodesMultiuserHeaderForEveryBlock();
    void multiuserChecksumExcludesHeader();
    void skipsGarbageBeforeAndBetweenFrames();
    void coalescesGarbageOfOneRead();
    void decodesSeveralFramesInOneRead_data();
    void decodesSeveralFramesInOneRead();
    void decodesByteByByte_data();
    void decodesByteByByte();
    void decodesStreamSplitAtEveryPosition();
    void dropsOversizedFrameAndResynchronises();
    void acceptsFrameOfExactlyMaximumSize();
    void dropsFrameEndedByCrWithoutLf();
    void treatsLfWithoutCrAsDataInsideAndGarbageOutside();
    void ignoresLeadsItDoesNotAccept();
    void multiuserIgnoresFrameWithoutHeader();
    void multiuserResynchronisesOnFalseHeaderStart();
    void resetDropsPartialFrame();
};

void TestStreamDecoder::decodesManualVectors_data() {
    QTest::addColumn<QByteArray>("wire");
    QTest::addColumn<char>("lead");
    QTest::addColumn<QByteArray>("body");
    QTest::newRow("?IFGWG") << QByteArray("?IFGWG4C\r\n") << '?' << QByteArray("IFGWG");
    QTest::newRow(":IFOROK") << QByteArray(":IFOROKFB\r\n") << ':' << QByteArray("IFOROK");
    QTest::newRow(":EEOK") << QByteArray(":EEOKA1\r\n") << ':' << QByteArray("EEOK");
    QTest::newRow(":EEFFFF") << QByteArray(":EEFFFF23\r\n") << ':' << QByteArray("EEFFFF");
    QTest::newRow("?EE0001") << QByteArray("?EE000175\r\n") << '?' << QByteArray("EE0001");
    QTest::newRow("!EE0005") << QByteArray("!EE00058F\r\n") << '!' << QByteArray("EE0005");
    QTest::newRow(":EEERR-43") << QByteArray(":EEERRFFFFFFD535\r\n") << ':'
                               << QByteArray("EEERRFFFFFFD5");
}

void TestStreamDecoder::decodesManualVectors() {
    QFETCH(QByteArray, wire);
    QFETCH(char, lead);
    QFETCH(QByteArray, body);
    StreamDecoder decoder(Framing::Standard, "?!:");
    const QList<DecodeEvent> events = decoder.feed(wire);
    QCOMPARE(events.size(), 1);
    QCOMPARE(events[0].kind, DecodeEvent::FrameOk);
    QCOMPARE(events[0].frame.lead, lead);
    QCOMPARE(events[0].frame.body, body);
    QVERIFY(events[0].frame.hasChecksum);
    QCOMPARE(events[0].raw, wire);
    QCOMPARE(decoder.pendingBytes(), 0);
}

void TestStreamDecoder::reportsWrongChecksum() {
    StreamDecoder decoder(Framing::Standard, "?");
    const QList<DecodeEvent> events = decoder.feed("?IFGWG4D\r\n");
    QCOMPARE(kinds(events), QList{DecodeEvent::BadChecksum});
    QCOMPARE(events[0].frame.body, QByteArray("IFGWG"));
    QVERIFY2(events[0].detail.contains("4C"), qPrintable(events[0].detail));
}

void TestStreamDecoder::reportsMissingChecksum() {
    StreamDecoder decoder(Framing::Standard, "?");
    QCOMPARE(kinds(decoder.feed("?\r\n")), QList{DecodeEvent::BadChecksum});
    QCOMPARE(kinds(decoder.feed("?IFGWG\r\n")), QList{DecodeEvent::BadChecksum});  // "WG" is no hex
}

void TestStreamDecoder::acceptsC0WithoutChecksumWhileChecksumsAreOn() {
    StreamDecoder device(Framing::Standard, "?!");
    const QList<DecodeEvent> request = device.feed("!C0\r\n");
    QCOMPARE(kinds(request), QList{DecodeEvent::FrameOk});
    QCOMPARE(request[0].frame.body, QByteArray("C0"));
    QVERIFY(!request[0].frame.hasChecksum);

    StreamDecoder pc(Framing::Standard, ":");
    const QList<DecodeEvent> reply = pc.feed(":C0OK\r\n");
    QCOMPARE(kinds(reply), QList{DecodeEvent::FrameOk});
    QCOMPARE(reply[0].frame.body, QByteArray("C0OK"));
}

void TestStreamDecoder::acceptsFramesWithoutChecksumWhenChecksumsAreOff() {
    StreamDecoder decoder(Framing::Standard, ":");
    decoder.setChecksumEnabled(false);
    const QList<DecodeEvent> events = decoder.feed(":IFOROK\r\n");
    QCOMPARE(kinds(events), QList{DecodeEvent::FrameOk});
    QCOMPARE(events[0].frame.body, QByteArray("IFOROK"));
    QVERIFY(!events[0].frame.hasChecksum);
}

void TestStreamDecoder::unescapesBinaryDataWithCrAndEsc() {
    const Frame frame = makeFrame('!', QByteArray("EE0001\x30\r\x1b\x1b\r\n\x00", 13));
    const QByteArray wire = encodeFrame(frame);
    QCOMPARE(wire.count('\x1b'), 2 + 4);  // the data's two ESCs, plus one before each CR and ESC

    StreamDecoder decoder(Framing::Standard, "!");
    const QList<DecodeEvent> events = decoder.feed(wire);
    QCOMPARE(kinds(events), QList{DecodeEvent::FrameOk});
    QCOMPARE(events[0].frame, frame);
}

void TestStreamDecoder::decodesMultiuserHeaderForEveryBlock() {
    StreamDecoder decoder(Framing::Multiuser, ":");
    for (int block = 0; block < 64; ++block) {
        const Frame frame = makeFrame(':', "EEOK", MultiuserAddress{block % 64, 63, block});
        const QList<DecodeEvent> events = decoder.feed(encodeFrame(frame));
        QCOMPARE(kinds(events), QList{DecodeEvent::FrameOk});
        QCOMPARE(events[0].frame, frame);
    }
}

void TestStreamDecoder::multiuserChecksumExcludesHeader() {
    // The manual vector with a header in front: checksum A1 stays valid.
    StreamDecoder decoder(Framing::Multiuser, ":");
    const QList<DecodeEvent> events = decoder.feed(QByteArray("\x45\xBF\xC9:EEOKA1\r\n"));
    QCOMPARE(kinds(events), QList{DecodeEvent::FrameOk});
    QCOMPARE(events[0].frame.address, std::optional(MultiuserAddress{5, 63, 9}));
    QCOMPARE(events[0].frame.body, QByteArray("EEOK"));
}

void TestStreamDecoder::skipsGarbageBeforeAndBetweenFrames() {
    StreamDecoder decoder(Framing::Standard, ":");
    const QByteArray wire =
        QByteArray("\x00\xFFnoise", 7) + ":EEOKA1\r\n" + "\r\n##" + ":EEFFFF23\r\n";
    const QList<DecodeEvent> events = decoder.feed(wire);
    QCOMPARE(kinds(events), (QList{DecodeEvent::Garbage, DecodeEvent::FrameOk, DecodeEvent::Garbage,
                                   DecodeEvent::FrameOk}));
    QCOMPARE(events[0].raw, QByteArray("\x00\xFFnoise", 7));
    QCOMPARE(events[2].raw, QByteArray("\r\n##"));
    QCOMPARE(events[3].frame.body, QByteArray("EEFFFF"));
}

void TestStreamDecoder::coalescesGarbageOfOneRead() {
    StreamDecoder decoder(Framing::Standard, ":");
    const QList<DecodeEvent> events = decoder.feed(QByteArray(300, 'x'));
    QCOMPARE(kinds(events), QList{DecodeEvent::Garbage});
    QCOMPARE(events[0].raw.size(), 300);
    QCOMPARE(decoder.pendingBytes(), 0);
}

void TestStreamDecoder::decodesSeveralFramesInOneRead_data() {
    QTest::addColumn<bool>("multiuser");
    QTest::newRow("standard") << false;
    QTest::newRow("multiuser") << true;
}

void TestStreamDecoder::decodesSeveralFramesInOneRead() {
    QFETCH(bool, multiuser);
    const QList<Frame> frames = sampleFrames(multiuser);
    StreamDecoder decoder(multiuser ? Framing::Multiuser : Framing::Standard, ":");
    const QList<DecodeEvent> events = decoder.feed(wireOf(frames));
    QCOMPARE(kinds(events), QList<DecodeEvent::Kind>(frames.size(), DecodeEvent::FrameOk));
    QCOMPARE(framesOf(events), frames);
}

void TestStreamDecoder::decodesByteByByte_data() {
    decodesSeveralFramesInOneRead_data();
}

void TestStreamDecoder::decodesByteByByte() {
    QFETCH(bool, multiuser);
    const QList<Frame> frames = sampleFrames(multiuser);
    StreamDecoder decoder(multiuser ? Framing::Multiuser : Framing::Standard, ":");
    const QList<DecodeEvent> events = feedByteByByte(decoder, "junk" + wireOf(frames));
    QCOMPARE(framesOf(events), frames);
    QCOMPARE(decoder.pendingBytes(), 0);
}

void TestStreamDecoder::decodesStreamSplitAtEveryPosition() {
    for (bool multiuser : {false, true}) {
        const QList<Frame> frames = sampleFrames(multiuser);
        const QByteArray wire = wireOf(frames);
        for (int split = 0; split <= wire.size(); ++split) {
            StreamDecoder decoder(multiuser ? Framing::Multiuser : Framing::Standard, ":");
            QList<DecodeEvent> events = decoder.feed(wire.left(split));
            events += decoder.feed(wire.mid(split));
            QVERIFY2(framesOf(events) == frames,
                     qPrintable(QStringLiteral("split at %1").arg(split)));
            QCOMPARE(kinds(events), QList<DecodeEvent::Kind>(frames.size(), DecodeEvent::FrameOk));
        }
    }
}

void TestStreamDecoder::dropsOversizedFrameAndResynchronises() {
    StreamDecoder decoder(Framing::Standard, "?");
    const QByteArray huge = "?" + QByteArray(3000, 'A') + "\r\n";
    QList<DecodeEvent> events;
    for (int i = 0; i < huge.size(); i += 100) {
        events += decoder.feed(huge.mid(i, 100));
        QVERIFY(decoder.pendingBytes() <= StreamDecoder::kMaxFrameBytes);
    }
    events += decoder.feed("?IFGWG4C\r\n");

    QCOMPARE(kinds(events).count(DecodeEvent::Oversized), 1);
    const QList<Frame> frames = framesOf(events);
    QCOMPARE(frames.size(), 1);
    QCOMPARE(frames[0].body, QByteArray("IFGWG"));
    qsizetype consumed = 0;
    for (const DecodeEvent& event : events) consumed += event.raw.size();
    QCOMPARE(consumed, huge.size() + 10);  // every byte is accounted for exactly once
}

void TestStreamDecoder::acceptsFrameOfExactlyMaximumSize() {
    // lead + body + 2 checksum + CR LF = kMaxFrameBytes
    const Frame frame = makeFrame('!', QByteArray(StreamDecoder::kMaxFrameBytes - 5, 'B'));
    const QByteArray wire = encodeFrame(frame);
    QCOMPARE(wire.size(), StreamDecoder::kMaxFrameBytes);
    StreamDecoder decoder(Framing::Standard, "!");
    QCOMPARE(framesOf(decoder.feed(wire)), QList{frame});

    const Frame tooBig = makeFrame('!', QByteArray(StreamDecoder::kMaxFrameBytes - 4, 'B'));
    const QList<DecodeEvent> events = decoder.feed(encodeFrame(tooBig));
    QCOMPARE(kinds(events), (QList{DecodeEvent::Oversized, DecodeEvent::Garbage}));
    QCOMPARE(events[0].raw.size(), StreamDecoder::kMaxFrameBytes);
    QCOMPARE(events[1].raw, QByteArray("\n"));  // the rest up to the frame's end
    QCOMPARE(decoder.pendingBytes(), 0);
}

void TestStreamDecoder::dropsFrameEndedByCrWithoutLf() {
    StreamDecoder decoder(Framing::Standard, "?");
    const QList<DecodeEvent> events = decoder.feed("?IFGWG4C\r?IFGWG4C\r\n");
    QCOMPARE(kinds(events), (QList{DecodeEvent::Garbage, DecodeEvent::FrameOk}));
    QCOMPARE(events[0].raw, QByteArray("?IFGWG4C\r"));
    QVERIFY2(events[0].detail.contains("CR without LF"), qPrintable(events[0].detail));
}

void TestStreamDecoder::treatsLfWithoutCrAsDataInsideAndGarbageOutside() {
    StreamDecoder decoder(Framing::Standard, "?");
    const Frame frame = makeFrame('?', "A\nB");
    const QList<DecodeEvent> events = decoder.feed("\n" + encodeFrame(frame));
    QCOMPARE(kinds(events), (QList{DecodeEvent::Garbage, DecodeEvent::FrameOk}));
    QCOMPARE(events[1].frame, frame);
}

void TestStreamDecoder::ignoresLeadsItDoesNotAccept() {
    StreamDecoder pc(Framing::Standard, ":");
    QCOMPARE(kinds(pc.feed("?IFGWG4C\r\n")), QList{DecodeEvent::Garbage});
}

void TestStreamDecoder::multiuserIgnoresFrameWithoutHeader() {
    StreamDecoder decoder(Framing::Multiuser, ":");
    QCOMPARE(kinds(decoder.feed(":EEOKA1\r\n")), QList{DecodeEvent::Garbage});
}

void TestStreamDecoder::multiuserResynchronisesOnFalseHeaderStart() {
    // 0x41 0x82 looks like a header start but 0x41 cannot be a block byte.
    StreamDecoder decoder(Framing::Multiuser, ":");
    const QByteArray wire = QByteArray("\x41\x82\x41\x82\xC3:EEOKA1\r\n");
    const QList<DecodeEvent> events = feedByteByByte(decoder, wire);
    const QList<Frame> frames = framesOf(events);
    QCOMPARE(frames.size(), 1);
    QCOMPARE(frames[0].address, std::optional(MultiuserAddress{1, 2, 3}));
    qsizetype garbage = 0;
    for (const DecodeEvent& event : events) {
        if (event.kind == DecodeEvent::Garbage) garbage += event.raw.size();
    }
    QCOMPARE(garbage, 2);
}

void TestStreamDecoder::resetDropsPartialFrame() {
    StreamDecoder decoder(Framing::Standard, "?");
    QVERIFY(decoder.feed("?IFG").isEmpty());
    QCOMPARE(decoder.pendingBytes(), 4);
    decoder.reset();
    QCOMPARE(decoder.pendingBytes(), 0);
    QCOMPARE(kinds(decoder.feed("WG4C\r\n")), QList{DecodeEvent::Garbage});
}

QTEST_GUILESS_MAIN(TestStreamDecoder)
#include "tst_stream_decoder.moc"
