// AsciiLink over a real pseudo-terminal: QSerialPort on the slave side,
// a scripted device on the master side.
#include "../../link/pty_device.h"

#include "comm/camcon/ascii/ascii_link.h"
#include "comm/camcon/ascii/command_codec.h"
#include "comm/transport/serial_transport.h"

#include <QtTest>

#include <atomic>
#include <memory>

using namespace cambench;
using namespace cambench::comm;
using namespace cambench::comm::test;

namespace {

const CommandSpec& spec(char kind, const char* name) {
    const CommandSpec* found = findCommand(kind, name);
    Q_ASSERT(found);
    return *found;
}

// ?NF reply for a track with one cam 100..200 and no more cams.
QByteArray nfReplyBody() {
    return encodeReplyBody(spec('?', "NF"),
                           Fields{{"on", qint64(100)}, {"off", qint64(200)}, {"more", qint64(0)}})
        .value();
}

DeviceAction answer(const Frame& request, const QByteArray& body) {
    return {{replyTo(request, body)}};
}

DeviceAction silence() {
    return {};
}

// The device, the port and the link of one test.
struct Rig {
    Rig(Framing framing, PtyDevice::Script script, int retries = 3, int timeoutMs = 300)
        : device(framing, std::move(script)),
          transport(device.slavePath(), SerialSettings{38400, 8, 'N', 1, 'N', true, true}),
          link(transport, scriptedSettings(framing, timeoutMs, retries)) {}

    // The script answers every frame itself, so the link sends no block
    // number synchronisation of its own (tested separately below).
    static AsciiSettings scriptedSettings(Framing framing, int timeoutMs, int retries) {
        AsciiSettings settings{framing, 5, 63, timeoutMs, 150000, retries};
        settings.syncBlockNumbers = false;
        return settings;
    }

    bool open() { return device.isValid() && transport.open().ok(); }

    PtyDevice device;
    SerialTransport transport;
    AsciiLink link;
};

}  // namespace

class TestProtocolLink : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void callDecodesReplyFields();
    void callSendsEncodedRequest();
    void timeoutThenSuccessOnRetry();
    void retryReusesBlockNumber();
    void newRequestTakesNextBlockNumber();
    void blockNumbersCountPerDestination();
    void blockNumberWrapsAfter63();
    void badChecksumReplyIsRetried();
    void malformedReplyIsRetried();
    void garbageBeforeReplyIsSkipped();
    void replySplitIntoSingleBytesIsDecoded();
    void deviceErrorReturnsCodeAndTextWithoutRetry();
    void notUnderstoodNamesCommandAndEpromDate();
    void replyFromOtherDeviceOrBlockIsIgnored();
    void allRepliesDroppedGivesCommunicationErrorAfterAllAttempts();
    void cancelDuringLongWaitReturnsCancelled();
    void commandWithoutReplyReturnsAfterWriting();
    void longCommandsUseLongTimeout();
    void rawReturnsReplyBody();
    void rawRejectsBadLead();
    void trafficSinkSeesBothDirections();
    void trafficSinkMasksUserNumbers();
    void statsCountBytesAndRetries();
};

void TestProtocolLink::callDecodesReplyFields() {
    Rig rig(Framing::Standard,
            [](const Frame& request, int) { return answer(request, nfReplyBody()); });
    QVERIFY(rig.open());
    const Result<Fields> reply =
        rig.link.call('?', "NF", Fields{{"program", qint64(3)}, {"output", qint64(1)}});
    QVERIFY2(reply.ok(), qPrintable(reply.error().message));
    QCOMPARE(reply->num("on"), 100);
    QCOMPARE(reply->num("off"), 200);
    QCOMPARE(reply->num("more"), 0);
}

void TestProtocolLink::callSendsEncodedRequest() {
    Rig rig(Framing::Standard,
            [](const Frame& request, int) { return answer(request, nfReplyBody()); });
    QVERIFY(rig.open());
    QVERIFY(rig.link.call('?', "NF", Fields{{"program", qint64(3)}, {"output", qint64(10)}}).ok());
    const QList<Frame> requests = rig.device.requests();
    QCOMPARE(requests.size(), 1);
    QCOMPARE(requests[0].lead, '?');
    QCOMPARE(requests[0].body, QByteArray("NF00030A"));
    QVERIFY(!requests[0].address.has_value());
}

void TestProtocolLink::timeoutThenSuccessOnRetry() {
    Rig rig(Framing::Standard, [](const Frame& request, int index) {
        return index == 0 ? silence() : answer(request, nfReplyBody());
    });
    QVERIFY(rig.open());
    const Result<Fields> reply = rig.link.call('?', "NF", Fields{{"program", qint64(0)}});
    QVERIFY2(reply.ok(), qPrintable(reply.error().message));
    QCOMPARE(reply->num("off"), 200);
    QCOMPARE(rig.device.requestCount(), 2);
    QCOMPARE(rig.link.stats().retries, 1);
}

void TestProtocolLink::retryReusesBlockNumber() {
    Rig rig(Framing::Multiuser, [](const Frame& request, int index) {
        return index == 0 ? silence() : answer(request, nfReplyBody());
    });
    QVERIFY(rig.open());
    QVERIFY(rig.link.call('?', "NF").ok());
    const QList<Frame> requests = rig.device.requests();
    QCOMPARE(requests.size(), 2);
    QVERIFY(requests[0].address && requests[1].address);
    QCOMPARE(requests[1].address->block, requests[0].address->block);
    QCOMPARE(requests[0].address->source, 63);
    QCOMPARE(requests[0].address->destination, 5);
}

void TestProtocolLink::newRequestTakesNextBlockNumber() {
    Rig rig(Framing::Multiuser,
            [](const Frame& request, int) { return answer(request, nfReplyBody()); });
    QVERIFY(rig.open());
    QVERIFY(rig.link.call('?', "NF").ok());
    QVERIFY(rig.link.call('?', "NF").ok());
    const QList<Frame> requests = rig.device.requests();
    QCOMPARE(requests.size(), 2);
    QCOMPARE(requests[1].address->block, (requests[0].address->block + 1) % 64);
}

void TestProtocolLink::blockNumbersCountPerDestination() {
    Rig rig(Framing::Multiuser,
            [](const Frame& request, int) { return answer(request, nfReplyBody()); });
    QVERIFY(rig.open());
    QVERIFY(rig.link.call('?', "NF").ok());  // device 5, block 0
    QVERIFY(rig.link.call('?', "NF").ok());  // device 5, block 1
    rig.link.setDevice(7);
    QVERIFY(rig.link.call('?', "NF").ok());  // device 7, block 0
    rig.link.setDevice(5);
    QVERIFY(rig.link.call('?', "NF").ok());  // device 5, block 2
    const QList<Frame> requests = rig.device.requests();
    QCOMPARE(requests.size(), 4);
    QCOMPARE(requests[2].address->destination, 7);
    QCOMPARE(requests[2].address->block, requests[0].address->block);
    QCOMPARE(requests[3].address->destination, 5);
    QCOMPARE(requests[3].address->block, (requests[1].address->block + 1) % 64);
}

void TestProtocolLink::blockNumberWrapsAfter63() {
    Rig rig(Framing::Multiuser,
            [](const Frame& request, int) { return answer(request, QByteArray("UNIT")); });
    QVERIFY(rig.open());
    for (int i = 0; i < 65; ++i) QVERIFY(rig.link.call('?', "UNIT").ok());
    const QList<Frame> requests = rig.device.requests();
    QCOMPARE(requests.size(), 65);
    QCOMPARE(requests[63].address->block, 63);
    QCOMPARE(requests[64].address->block, 0);
}

void TestProtocolLink::badChecksumReplyIsRetried() {
    Rig rig(Framing::Standard, [](const Frame& request, int index) {
        const QByteArray reply = replyTo(request, nfReplyBody());
        return DeviceAction{{index == 0 ? withBadChecksum(reply) : reply}};
    });
    QVERIFY(rig.open());
    const Result<Fields> reply = rig.link.call('?', "NF");
    QVERIFY2(reply.ok(), qPrintable(reply.error().message));
    QCOMPARE(rig.device.requestCount(), 2);
    QCOMPARE(rig.link.stats().badFrames, 1);
}

void TestProtocolLink::malformedReplyIsRetried() {
    Rig rig(Framing::Standard, [](const Frame& request, int index) {
        return answer(request, index == 0 ? QByteArray("NF12") : nfReplyBody());
    });
    QVERIFY(rig.open());
    QVERIFY(rig.link.call('?', "NF").ok());
    QCOMPARE(rig.device.requestCount(), 2);
}

void TestProtocolLink::garbageBeforeReplyIsSkipped() {
    Rig rig(Framing::Standard, [](const Frame& request, int) {
        return DeviceAction{{QByteArray("\x01\xff noise\r\n"), replyTo(request, nfReplyBody())}, 5};
    });
    QVERIFY(rig.open());
    const Result<Fields> reply = rig.link.call('?', "NF");
    QVERIFY2(reply.ok(), qPrintable(reply.error().message));
    QCOMPARE(reply->num("on"), 100);
    QCOMPARE(rig.device.requestCount(), 1);
}

void TestProtocolLink::replySplitIntoSingleBytesIsDecoded() {
    Rig rig(Framing::Multiuser, [](const Frame& request, int) {
        DeviceAction action;
        for (const char byte : replyTo(request, nfReplyBody()))
            action.chunks.append(QByteArray(1, byte));
        action.chunkDelayMs = 2;
        return action;
    });
    QVERIFY(rig.open());
    const Result<Fields> reply = rig.link.call('?', "NF");
    QVERIFY2(reply.ok(), qPrintable(reply.error().message));
    QCOMPARE(reply->num("off"), 200);
    QCOMPARE(rig.device.requestCount(), 1);
}

void TestProtocolLink::deviceErrorReturnsCodeAndTextWithoutRetry() {
    Rig rig(Framing::Standard, [](const Frame& request, int) {
        return answer(request, errorReplyBody(spec('?', "NF"), -43));
    });
    QVERIFY(rig.open());
    const Result<Fields> reply = rig.link.call('?', "NF");
    QVERIFY(!reply.ok());
    QCOMPARE(reply.error().kind, ErrorKind::DeviceError);
    QCOMPARE(reply.error().deviceCode, -43);
    QVERIFY2(
        reply.error().message.startsWith(QLatin1String("?NF: the device reported error -43: ")),
        qPrintable(reply.error().message));
    QVERIFY(reply.error().message.size() >
            QStringLiteral("?NF: the device reported error -43: ").size());
    QCOMPARE(rig.device.requestCount(), 1);
}

void TestProtocolLink::notUnderstoodNamesCommandAndEpromDate() {
    Rig rig(Framing::Standard, [](const Frame& request, int) {
        return answer(request, notUnderstoodBody("12.03.2004"));
    });
    QVERIFY(rig.open());
    const Result<Fields> reply = rig.link.call('?', "NF");
    QVERIFY(!reply.ok());
    QCOMPARE(reply.error().kind, ErrorKind::NotUnderstood);
    QVERIFY2(reply.error().message.contains(QLatin1String("?NF")),
             qPrintable(reply.error().message));
    QVERIFY2(reply.error().message.contains(QLatin1String("12.03.2004")),
             qPrintable(reply.error().message));
    QCOMPARE(rig.device.requestCount(), 1);
}

void TestProtocolLink::replyFromOtherDeviceOrBlockIsIgnored() {
    Rig rig(Framing::Multiuser, [](const Frame& request, int) {
        const int block = request.address->block;
        const QByteArray otherBody =
            encodeReplyBody(spec('?', "NF"), Fields{{"on", qint64(1)}}).value();
        return DeviceAction{{replyFrom(request, otherBody, 6, block),             // other device
                             replyFrom(request, otherBody, 5, (block + 1) % 64),  // other block
                             replyTo(request, nfReplyBody())}};
    });
    QVERIFY(rig.open());
    const Result<Fields> reply = rig.link.call('?', "NF");
    QVERIFY2(reply.ok(), qPrintable(reply.error().message));
    QCOMPARE(reply->num("on"), 100);
    QCOMPARE(rig.device.requestCount(), 1);
}

void TestProtocolLink::allRepliesDroppedGivesCommunicationErrorAfterAllAttempts() {
    Rig rig(
        Framing::Multiuser, [](const Frame&, int) { return silence(); }, 3, 100);
    QVERIFY(rig.open());
    const Result<Fields> reply = rig.link.call('?', "NF");
    QVERIFY(!reply.ok());
    QCOMPARE(reply.error().kind, ErrorKind::Communication);
    const QString message = reply.error().message;
    QVERIFY2(message.contains(QLatin1String("device 5")), qPrintable(message));
    QVERIFY2(message.contains(QLatin1String("?NF")), qPrintable(message));
    QVERIFY2(message.contains(QLatin1String("4 attempts of 100 ms")), qPrintable(message));
    QVERIFY2(message.contains(QLatin1String("38400")), qPrintable(message));
    QVERIFY2(message.contains(QLatin1String("Multiuser")), qPrintable(message));
    QTRY_COMPARE(rig.device.requestCount(), 4);
}

void TestProtocolLink::cancelDuringLongWaitReturnsCancelled() {
    std::atomic_bool cancel{false};
    // The device cancels once it holds the request, so the link is waiting;
    // the timeout is long enough that only cancelling can end the call.
    Rig rig(
        Framing::Standard,
        [&cancel](const Frame&, int) {
            cancel = true;
            return silence();
        },
        0, 120000);
    QVERIFY(rig.open());
    rig.link.setCancelFlag(&cancel);
    const Result<Fields> reply = rig.link.call('?', "NF");
    QVERIFY(!reply.ok());
    QCOMPARE(reply.error().kind, ErrorKind::Cancelled);
}

void TestProtocolLink::commandWithoutReplyReturnsAfterWriting() {
    Rig rig(
        Framing::Standard, [](const Frame&, int) { return silence(); }, 3, 120000);
    QVERIFY(rig.open());
    const Result<Fields> reply = rig.link.call('!', "GRESET");
    QVERIFY2(reply.ok(), qPrintable(reply.error().message));
    QTRY_COMPARE(rig.device.requestCount(), 1);
    QCOMPARE(rig.device.requests()[0].body, QByteArray("GRESET"));
}

void TestProtocolLink::longCommandsUseLongTimeout() {
    // The normal timeout is too short for the device's delay, the long one
    // is not: !CA succeeds only if it waits with the long timeout.
    Rig rig(
        Framing::Standard,
        [](const Frame& request, int) {
            return DeviceAction{{replyTo(request, okReplyBody(spec('!', "CA")))}, 400};
        },
        0, 50);
    QVERIFY(rig.open());
    const Result<Fields> reply = rig.link.call('!', "CA");
    QVERIFY2(reply.ok(), qPrintable(reply.error().message));
    QCOMPARE(rig.device.requestCount(), 1);
}

void TestProtocolLink::rawReturnsReplyBody() {
    Rig rig(Framing::Multiuser, [](const Frame& request, int) {
        return answer(request, QByteArray("IFGWG   12.345"));
    });
    QVERIFY(rig.open());
    const Result<QByteArray> reply = rig.link.raw('?', "IFGWG");
    QVERIFY2(reply.ok(), qPrintable(reply.error().message));
    QCOMPARE(*reply, QByteArray("IFGWG   12.345"));
    QCOMPARE(rig.device.requests()[0].body, QByteArray("IFGWG"));
}

void TestProtocolLink::rawRejectsBadLead() {
    Rig rig(Framing::Standard, [](const Frame&, int) { return silence(); });
    QVERIFY(rig.open());
    const Result<QByteArray> reply = rig.link.raw(':', "IFGWG");
    QVERIFY(!reply.ok());
    QCOMPARE(reply.error().kind, ErrorKind::Usage);
    QCOMPARE(rig.device.requestCount(), 0);
}

void TestProtocolLink::trafficSinkSeesBothDirections() {
    Rig rig(Framing::Standard,
            [](const Frame& request, int) { return answer(request, QByteArray("UNIT")); });
    QVERIFY(rig.open());
    QList<TrafficEntry> entries;
    rig.link.setTrafficSink([&entries](const TrafficEntry& entry) { entries.append(entry); });
    QVERIFY(rig.link.call('?', "UNIT").ok());
    QCOMPARE(entries.size(), 2);
    QVERIFY(entries[0].outgoing);
    QCOMPARE(entries[0].bytes, encodeFrame(Frame{'?', "UNIT", std::nullopt, true}));
    QVERIFY(!entries[1].outgoing);
    QCOMPARE(entries[1].bytes, encodeFrame(Frame{':', "UNIT", std::nullopt, true}));
    QVERIFY(entries[0].time.isValid());
}

void TestProtocolLink::trafficSinkMasksUserNumbers() {
    const CommandSpec& query = spec('?', "USER");
    const QByteArray userReply = encodeReplyBody(query, Fields{{"name", QByteArray("Meier")},
                                                               {"number", QByteArray("4711")},
                                                               {"access", QByteArray(32, '\x01')},
                                                               {"all", qint64(1)},
                                                               {"rights", qint64(3)}})
                                     .value();
    Rig rig(Framing::Multiuser, [&](const Frame& request, int) {
        return answer(request, request.lead == '?' ? userReply : okReplyBody(spec('!', "USER")));
    });
    QVERIFY(rig.open());
    QList<TrafficEntry> entries;
    rig.link.setTrafficSink([&entries](const TrafficEntry& entry) { entries.append(entry); });

    const Result<Fields> user = rig.link.call('?', "USER", Fields{{"index", qint64(0)}});
    QVERIFY2(user.ok(), qPrintable(user.error().message));
    QCOMPARE(user->bytes("number"), QByteArray("4711"));  // the caller gets the real number
    const Result<Fields> written = rig.link.call('!', "USER",
                                                 Fields{{"oldNumber", QByteArray("4711")},
                                                        {"name", QByteArray("Meier")},
                                                        {"number", QByteArray("0815")},
                                                        {"access", QByteArray(32, '\0')}});
    QVERIFY2(written.ok(), qPrintable(written.error().message));
    // The device saw the real numbers, the sink only stars.
    QVERIFY(rig.device.requests()[1].body.contains("4711"));
    QCOMPARE(entries.size(), 4);
    for (const TrafficEntry& entry : entries) {
        QVERIFY2(!entry.bytes.contains("4711"), entry.bytes.constData());
        QVERIFY2(!entry.bytes.contains("0815"), entry.bytes.constData());
    }
    QVERIFY(entries[1].bytes.contains("******"));
    QVERIFY(entries[1].bytes.contains("Meier"));
    QCOMPARE(entries[1].bytes.count("******"), 1);
    QCOMPARE(entries[2].bytes.count("******"), 2);
}

void TestProtocolLink::statsCountBytesAndRetries() {
    Rig rig(
        Framing::Standard,
        [](const Frame& request, int index) {
            return index == 0 ? silence() : answer(request, QByteArray("UNIT"));
        },
        3, 100);
    QVERIFY(rig.open());
    QVERIFY(rig.link.call('?', "UNIT").ok());
    const qint64 requestBytes = encodeFrame(Frame{'?', "UNIT", std::nullopt, true}).size();
    QCOMPARE(rig.link.stats().requests, 1);
    QCOMPARE(rig.link.stats().retries, 1);
    QCOMPARE(rig.link.stats().bytesSent, 2 * requestBytes);
    QCOMPARE(rig.link.stats().bytesReceived,
             encodeFrame(Frame{':', "UNIT", std::nullopt, true}).size());
    rig.link.resetStats();
    QCOMPARE(rig.link.stats().requests, 0);
}

QTEST_GUILESS_MAIN(TestProtocolLink)
#include "tst_ascii_link.moc"
