#pragma once

#include <QList>
#include <QString>
#include <QStringList>

namespace cambench {

// A list a device hands out one entry per request, with a cursor on the
// device ("start" and "next", as the CamCon's ?USER00 / ?USER01). Without
// sequence numbers a "next" whose reply was lost and that went out again may
// have moved the cursor twice: the walk then cannot tell a skipped entry from
// none. Walks that each lose their place at different steps still hold the
// whole list between them; WalkedList merges them (issue 12, point 1).
//
// Entries are told apart by a key (for users: name and number), and the
// device's order of the list is fixed while it is read.

// One walk from "start" on, as far as it came.
struct ListWalk {
    struct Step {
        QString key;           // the entry this step brought
        bool maySkip = false;  // an entry between the previous one and this may be missing
    };
    QList<Step> steps;
    bool reachedEnd = false;  // the device said "no more entries"
    bool endMaySkip = false;  // ... after a step that may have skipped an entry
};

// What the walks so far establish.
struct WalkedList {
    QStringList keys;       // every entry seen, in the device's order as far as known
    bool complete = false;  // every neighbouring pair and the end were seen with nothing skipped
    // Where an entry may be missing: pairs of neighbouring keys in `keys`
    // ("" for the start or the end of the list); empty when complete.
    QList<QPair<QString, QString>> uncertainGaps;
    // The walks contradict each other (the list changed while it was read,
    // or two entries share a key): the list cannot be trusted.
    bool contradicted = false;
    QString contradictionAt;  // an entry whose neighbour differed between walks ("" the start)
};

WalkedList mergeWalks(const QList<ListWalk>& walks);

}  // namespace cambench
