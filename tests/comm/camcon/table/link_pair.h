#pragma once

#include "comm/camcon/table/link_3964r.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <functional>

namespace cambench::comm::table::test {

// Two Link3964R wired back to back on a fake clock: what one writes reaches
// the other at the same instant; time moves only to the next deadline. A
// filter per direction can drop or change bytes on the wire.
class LinkPair {
public:
    struct Side {
        Link3964R link;
        QList<QByteArray> received;
        int sendDone = 0;
        QList<QString> sendFailed;
        QByteArray wrote;     // every byte this side put on the line
        QByteArray inFlight;  // written, not yet delivered to the other side
        std::function<QByteArray(const QByteArray&)> filter;  // applied before delivery
    };

    LinkPair(Link3964R::Timing timing = {});

    Side pc;      // high priority
    Side device;  // low priority
    qint64 now = 0;
    // "pc>02", "dev>10", ... in the order bytes were delivered.
    QList<QString> transcript;

    void send(Side& side, const QByteArray& telegram);
    // Delivers bytes and follows deadlines until nothing is left to do or
    // the clock would pass `untilMs`.
    void run(qint64 untilMs = 60'000);

private:
    void apply(Side& side, const Actions& actions);
    Side& other(Side& side) { return &side == &pc ? device : pc; }
};

}  // namespace cambench::comm::table::test
