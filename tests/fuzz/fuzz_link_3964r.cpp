// libFuzzer target for the 3964R state machine. The same function runs in
// normal builds through fuzz_link_3964r_replay_main.cpp
// (fuzz_link_3964r_replay).
#include "comm/camcon/table/frame_3964r.h"
#include "comm/camcon/table/link_3964r.h"
#include "fuzz_check.h"

#include <cstdint>

using namespace cambench::comm::table;

namespace {

constexpr int kMax = Link3964R::kMaxTelegramBytes;

// What the link may put on the line: control bytes, and the block of the
// telegram it was asked to send (nothing else, whatever it reads).
void checkWrite(QByteArrayView write, const QByteArray& ownBlock) {
    while (!write.isEmpty()) {
        if (!ownBlock.isEmpty() && write.startsWith(ownBlock)) {
            write = write.sliced(ownBlock.size());
            continue;
        }
        const char c = write[0];
        FUZZ_CHECK(c == kDle || c == kNak || (c == kStx && !ownBlock.isEmpty()));
        write = write.sliced(1);
    }
}

struct Outcome {
    int done = 0;
    int failed = 0;
};

void checkActions(const Link3964R& link, const Actions& actions, qint64 now,
                  const QByteArray& ownBlock, Outcome& outcome) {
    for (const QByteArray& telegram : actions.received) FUZZ_CHECK(telegram.size() <= kMax);
    FUZZ_CHECK(link.bufferedBytes() >= 0 && link.bufferedBytes() <= kMax);
    FUZZ_CHECK(link.nextDeadlineMs() == -1 || link.nextDeadlineMs() > now);
    FUZZ_CHECK(!(actions.sendDone && actions.sendFailed));
    checkWrite(actions.write, ownBlock);
    if (actions.sendDone) ++outcome.done;
    if (actions.sendFailed) ++outcome.failed;
    if (actions.sendDone || actions.sendFailed) FUZZ_CHECK(!link.sending());
}

// Feeds the input in chunks with gaps between them, both derived from the
// input so that a crash reproduces; the gaps now and then pass the
// character and acknowledgement delays.
void runReceiver(QByteArrayView input, Link3964R::Priority priority, bool sendFirst) {
    Link3964R link(priority);
    const QByteArray telegram = input.first(qMin<qsizetype>(input.size(), 16)).toByteArray();
    const bool sending = sendFirst && !telegram.isEmpty();
    const QByteArray ownBlock = sending ? encodeBlock3964r(telegram) : QByteArray();
    Outcome outcome;
    qint64 now = 0;
    if (sending) checkActions(link, link.send(telegram, now), now, ownBlock, outcome);

    quint32 state = quint32(input.size()) * 2654435761u + (input.isEmpty() ? 0u : quint8(input[0]));
    qsizetype position = 0;
    while (position < input.size()) {
        state = state * 1103515245u + 12345u;
        const qsizetype chunk = qMin<qsizetype>(1 + (state >> 16) % 61, input.size() - position);
        now += (state >> 8) % 16 == 0 ? 2100 : (state >> 4) % 300;
        checkActions(link, link.feed(input.sliced(position, chunk), now), now, ownBlock, outcome);
        position += chunk;
        if ((state >> 12) % 4 == 0) checkActions(link, link.poll(now), now, ownBlock, outcome);
    }

    // Left alone, every transfer ends: all attempts of a send time out at most.
    for (int i = 0; i < 4 * Link3964R::Timing().attempts + 8 && !link.idle(); ++i) {
        FUZZ_CHECK(link.nextDeadlineMs() >= 0);
        now = link.nextDeadlineMs();
        checkActions(link, link.poll(now), now, ownBlock, outcome);
    }
    FUZZ_CHECK(link.idle());
    FUZZ_CHECK(link.nextDeadlineMs() == -1);
    FUZZ_CHECK(link.bufferedBytes() == 0);
    FUZZ_CHECK(outcome.done + outcome.failed == (sending ? 1 : 0));

    // And it is in step again: a good block is received as sent.
    const QByteArray probe = QByteArray::fromHex("00004544050A0007FFFF");
    now += 1;
    Actions start = link.feed(QByteArrayView(&kStx, 1), now);
    FUZZ_CHECK(start.write == QByteArray(1, kDle));
    Actions block = link.feed(encodeBlock3964r(probe), now + 1);
    FUZZ_CHECK(block.write == QByteArray(1, kDle));
    FUZZ_CHECK(block.received.size() == 1 && block.received[0] == probe);
}

// A perfect wire between two links delivers any telegram unchanged.
void runRoundTrip(QByteArrayView input, Link3964R::Priority senderPriority) {
    const QByteArray telegram = input.first(qMin<qsizetype>(input.size(), kMax)).toByteArray();
    if (telegram.isEmpty()) return;
    const Link3964R::Priority receiverPriority = senderPriority == Link3964R::Priority::High
                                                     ? Link3964R::Priority::Low
                                                     : Link3964R::Priority::High;
    Link3964R sender(senderPriority);
    Link3964R receiver(receiverPriority);
    Actions toReceiver = sender.send(telegram, 0);
    QList<QByteArray> received;
    bool done = false;
    for (int i = 0; i < 8 && !toReceiver.write.isEmpty(); ++i) {
        const Actions atReceiver = receiver.feed(toReceiver.write, 0);
        received += atReceiver.received;
        toReceiver = sender.feed(atReceiver.write, 0);
        done = done || toReceiver.sendDone;
        FUZZ_CHECK(!toReceiver.sendFailed);
    }
    FUZZ_CHECK(done);
    FUZZ_CHECK(received.size() == 1 && received[0] == telegram);
    FUZZ_CHECK(sender.idle() && receiver.idle());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const QByteArrayView input(reinterpret_cast<const char*>(data), qsizetype(size));
    for (Link3964R::Priority priority : {Link3964R::Priority::High, Link3964R::Priority::Low}) {
        runReceiver(input, priority, false);
        runReceiver(input, priority, true);
        runRoundTrip(input, priority);
    }
    return 0;
}
