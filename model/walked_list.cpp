#include "walked_list.h"

#include <QHash>
#include <QSet>

#include <algorithm>
#include <limits>

namespace cambench {

namespace {

// The start and the end of the list as nodes of the order; keys of entries
// never hold control characters, so these cannot clash with one.
const QString kStart = QStringLiteral("\x01start");
const QString kEnd = QStringLiteral("\x01end");

struct Edge {
    QString from;
    QString to;
    bool sure = false;  // nothing between from and to was skipped
};

QList<Edge> edgesOf(const ListWalk& walk) {
    QList<Edge> edges;
    QString previous = kStart;
    for (const ListWalk::Step& step : walk.steps) {
        edges.append({previous, step.key, !step.maySkip});
        previous = step.key;
    }
    if (walk.reachedEnd) edges.append({previous, kEnd, !walk.endMaySkip});
    return edges;
}

QString shown(const QString& node) {
    return node == kStart || node == kEnd ? QString() : node;
}

// Orders every node seen so that each walk's order holds (a topological
// sort; the walks are subsequences of one list). Ties only occur inside
// uncertain parts: there the node seen furthest down a walk goes last, as
// a skip only ever moves an entry up.
QStringList orderOf(const QStringList& nodes, const QList<Edge>& edges,
                    const QHash<QString, int>& deepest, bool* cycle) {
    QHash<QString, int> incoming;
    QHash<QString, QStringList> next;
    for (const QString& node : nodes) incoming.insert(node, 0);
    QSet<QPair<QString, QString>> seen;
    for (const Edge& e : edges) {
        if (seen.contains({e.from, e.to})) continue;
        seen.insert({e.from, e.to});
        next[e.from].append(e.to);
        ++incoming[e.to];
    }
    QStringList order;
    QStringList ready;
    for (const QString& node : nodes)
        if (incoming.value(node) == 0) ready.append(node);
    while (!ready.isEmpty()) {
        qsizetype pick = 0;
        for (qsizetype i = 1; i < ready.size(); ++i)
            if (deepest.value(ready.at(i)) < deepest.value(ready.at(pick))) pick = i;
        const QString node = ready.takeAt(pick);
        order.append(node);
        for (const QString& to : next.value(node))
            if (--incoming[to] == 0) ready.append(to);
    }
    *cycle = order.size() != nodes.size();
    return order;
}

}  // namespace

WalkedList mergeWalks(const QList<ListWalk>& walks) {
    WalkedList result;
    QStringList nodes{kStart};
    QList<Edge> edges;
    bool endSeen = false;
    QHash<QString, int> deepest;  // the furthest step of any walk that brought the key
    for (const ListWalk& walk : walks) {
        for (qsizetype i = 0; i < walk.steps.size(); ++i) {
            const QString& key = walk.steps.at(i).key;
            if (!nodes.contains(key)) nodes.append(key);
            deepest[key] = std::max(deepest.value(key), int(i) + 1);
        }
        endSeen = endSeen || walk.reachedEnd;
        edges += edgesOf(walk);
    }
    if (endSeen) nodes.append(kEnd);

    // A sure edge says "to" directly follows "from": two different sure
    // followers (or predecessors) mean the list is not one fixed list.
    QHash<QString, QString> sureNext;
    QHash<QString, QString> surePrevious;
    for (const Edge& e : edges) {
        if (!e.sure) continue;
        const QString next = sureNext.value(e.from, e.to);
        const QString previous = surePrevious.value(e.to, e.from);
        if (next != e.to || previous != e.from) {
            result.contradicted = true;
            result.contradictionAt = shown(next != e.to ? e.from : e.to);
            return result;
        }
        sureNext.insert(e.from, e.to);
        surePrevious.insert(e.to, e.from);
    }

    bool cycle = false;
    deepest.insert(kEnd, std::numeric_limits<int>::max());
    const QStringList order = orderOf(nodes, edges, deepest, &cycle);
    if (cycle) {
        result.contradicted = true;
        return result;
    }
    for (const QString& node : order)
        if (node != kStart && node != kEnd) result.keys.append(node);

    // Complete: the sure chain from the start runs through every entry to the end.
    for (qsizetype i = 0; i + 1 < order.size(); ++i) {
        if (sureNext.value(order.at(i)) != order.at(i + 1))
            result.uncertainGaps.append({shown(order.at(i)), shown(order.at(i + 1))});
    }
    if (!endSeen) result.uncertainGaps.append({shown(order.last()), QString()});
    result.complete = result.uncertainGaps.isEmpty();
    return result;
}

}  // namespace cambench
