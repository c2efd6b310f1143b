#include "link_pair.h"

#include <algorithm>

namespace cambench::comm::table::test {

LinkPair::LinkPair(Link3964R::Timing timing)
    : pc{Link3964R(Link3964R::Priority::High, timing), {}, 0, {}, {}, {}, {}},
      device{Link3964R(Link3964R::Priority::Low, timing), {}, 0, {}, {}, {}, {}} {}

void LinkPair::send(Side& side, const QByteArray& telegram) {
    apply(side, side.link.send(telegram, now));
}

void LinkPair::apply(Side& side, const Actions& actions) {
    side.received += actions.received;
    if (actions.sendDone) ++side.sendDone;
    if (actions.sendFailed) side.sendFailed.append(*actions.sendFailed);
    side.wrote += actions.write;
    side.inFlight += actions.write;
}

void LinkPair::run(qint64 untilMs) {
    for (int step = 0; step < 100'000; ++step) {
        bool delivered = false;
        for (Side* from : {&pc, &device}) {
            if (from->inFlight.isEmpty()) continue;
            QByteArray bytes = std::exchange(from->inFlight, {});
            if (from->filter) bytes = from->filter(bytes);
            if (bytes.isEmpty()) continue;
            transcript.append(QStringLiteral("%1>%2").arg(
                from == &pc ? QStringLiteral("pc") : QStringLiteral("dev"),
                QString::fromLatin1(bytes.toHex(' '))));
            Side& to = other(*from);
            apply(to, to.link.feed(bytes, now));
            delivered = true;
        }
        if (delivered) continue;
        qint64 next = -1;
        for (const Side* side : {&pc, &device}) {
            const qint64 deadline = side->link.nextDeadlineMs();
            if (deadline >= 0 && (next < 0 || deadline < next)) next = deadline;
        }
        if (next < 0 || next > untilMs) return;
        now = std::max(now, next);
        apply(pc, pc.link.poll(now));
        apply(device, device.link.poll(now));
    }
}

}  // namespace cambench::comm::table::test
