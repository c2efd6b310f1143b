// TableBackend on a fake clock against the device's side of 3964R: what
// the request engine sees of one request, its reply, and link failures.
#include "comm/camcon/table/frame_3964r.h"
#include "comm/camcon/table/link_3964r.h"
#include "comm/camcon/table/table_backend.h"

#include <QtTest>

using namespace cambench::comm;
using namespace cambench::comm::table;

namespace {

QByteArray hex(const char* text) {
    return QByteArray::fromHex(text);
}

const QByteArray kStxByte(1, kStx);
const QByteArray kDleByte(1, kDle);

Request readRequest() {
    Request request;
    request.label = QStringLiteral("RK512 read of area 5");
    request.message = hex("00004544050a0007ffff");  // notes 7
    request.longestReplyBytes = 4 + 14;
    return request;
}

QList<Incoming> messagesOf(const BackendStep& step) {
    QList<Incoming> messages;
    for (const Incoming& in : step.incoming)
        if (in.kind != Incoming::Garbage) messages.append(in);
    return messages;
}

}  // namespace

class TestTableBackend : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void requestIsSentOnceTheDeviceTookTheBlock();
    void replyArrivesAsTheDevicesOwnTransfer();
    void telegramBeforeTheAcknowledgementIsNoAnswer();
    void linkFailureEndsEveryFurtherAttemptAtOnce();
    void neverRetriedRequestStopsWhenTheBlockMayHaveArrived();
    void wireBytesCountHandshakesAndDoubledDles();
};

void TestTableBackend::requestIsSentOnceTheDeviceTookTheBlock() {
    TableBackend pc(Rk512Variant::N96);
    Link3964R device(Link3964R::Priority::Low);
    const Request request = readRequest();
    pc.beginRequest(request);
    BackendStep step = pc.startAttempt(request, 1, 0);
    QCOMPARE(step.write, kStxByte);
    QVERIFY(!step.sent);
    Actions answer = device.feed(step.write, 1);
    QCOMPARE(answer.write, kDleByte);
    step = pc.feed(answer.write, 2);
    QCOMPARE(step.write, encodeBlock3964r(request.message));
    QVERIFY(!step.sent);
    answer = device.feed(step.write, 3);
    QCOMPARE(answer.received, QList<QByteArray>{request.message});
    step = pc.feed(answer.write, 4);
    QVERIFY(step.sent);
    QVERIFY(step.linkFailure.isEmpty());
}

void TestTableBackend::replyArrivesAsTheDevicesOwnTransfer() {
    TableBackend pc(Rk512Variant::N96);
    Link3964R device(Link3964R::Priority::Low);
    const Request request = readRequest();
    pc.beginRequest(request);
    Actions answer = device.feed(pc.startAttempt(request, 1, 0).write, 1);
    answer = device.feed(pc.feed(answer.write, 2).write, 3);
    QVERIFY(pc.feed(answer.write, 4).sent);

    const QByteArray reply = hex("00000000") + QByteArray(14, '\x10');  // DLEs doubled on the line
    answer = device.send(reply, 5);
    BackendStep step = pc.feed(answer.write, 6);  // the device's STX
    QCOMPARE(step.write, kDleByte);
    QVERIFY(messagesOf(step).isEmpty());
    answer = device.feed(step.write, 7);  // the device sends its block
    step = pc.feed(answer.write, 8);
    QCOMPARE(step.write, kDleByte);  // the PC acknowledges
    const QList<Incoming> messages = messagesOf(step);
    QCOMPARE(messages.size(), 1);
    QCOMPARE(messages.first().kind, Incoming::Message);
    QCOMPARE(messages.first().message, reply);
    QCOMPARE(messages.first().wire, answer.write);
    QVERIFY(device.feed(step.write, 9).sendDone);
}

void TestTableBackend::telegramBeforeTheAcknowledgementIsNoAnswer() {
    // The device took the block, but its DLE was lost and its reply's STX
    // came first: the PC cannot know which telegram that reply answers.
    TableBackend pc(Rk512Variant::N96);
    const Request request = readRequest();
    pc.beginRequest(request);
    pc.startAttempt(request, 1, 0);
    pc.feed(kDleByte, 1);  // block out
    BackendStep step = pc.feed(kStxByte, 2);
    QCOMPARE(step.write, kDleByte);  // receives it all the same
    step = pc.feed(encodeBlock3964r(hex("00000000")), 3);
    QVERIFY(!step.sent);
    const QList<Incoming> messages = messagesOf(step);
    QCOMPARE(messages.size(), 1);
    QCOMPARE(messages.first().kind, Incoming::Foreign);
    // ... and its link tries the request again.
    QCOMPARE(step.write, kDleByte + kStxByte);
}

void TestTableBackend::linkFailureEndsEveryFurtherAttemptAtOnce() {
    TableBackend pc(Rk512Variant::N96, Timing3964R{100, 20, 3});
    const Request request = readRequest();
    pc.beginRequest(request);
    pc.startAttempt(request, 1, 0);
    QString failure;
    int stx = 1;
    for (int guard = 0; guard < 20 && failure.isEmpty(); ++guard) {
        const BackendStep step = pc.poll(pc.nextTimerMs());
        stx += int(step.write.count(kStx));
        failure = step.linkFailure;
    }
    QCOMPARE(stx, 3);
    QVERIFY2(failure.contains(QLatin1String("3 attempts")), qPrintable(failure));
    // The engine's next attempt must not start six more.
    const BackendStep again = pc.startAttempt(request, 2, 10000);
    QVERIFY(again.write.isEmpty());
    QCOMPARE(again.linkFailure, failure);
    // A new request starts afresh.
    pc.beginRequest(request);
    QCOMPARE(pc.startAttempt(request, 1, 10001).write, kStxByte);
}

void TestTableBackend::neverRetriedRequestStopsWhenTheBlockMayHaveArrived() {
    TableBackend pc(Rk512Variant::N96);
    Request request = readRequest();
    request.retry = RetryPolicy::Never;
    pc.beginRequest(request);
    pc.startAttempt(request, 1, 0);
    pc.feed(kDleByte, 1);  // the block goes out; no DLE comes back
    const BackendStep step = pc.poll(pc.nextTimerMs());
    QVERIFY(step.write.isEmpty());
    QVERIFY2(step.linkFailure.contains(QLatin1String("may have executed")),
             qPrintable(step.linkFailure));
}

void TestTableBackend::wireBytesCountHandshakesAndDoubledDles() {
    TableBackend pc(Rk512Variant::N96);
    Request request = readRequest();
    request.message = hex("0010");
    // STX, DLE, 00 10 10 DLE ETX BCC, DLE
    QCOMPARE(pc.requestWireBytes(request), 3 + 6);
    request.longestReplyBytes = 10;
    QCOMPARE(pc.replyWireBytes(request), 3 + 3 + 20);
}

QTEST_GUILESS_MAIN(TestTableBackend)
#include "tst_table_backend.moc"
