// Merging walks through a device list that may skip an entry after a
// repeated step (issue 12, point 1): complete only when every neighbouring
// pair and the end were seen with nothing skipped, never a wrong list.
#include <QRandomGenerator>
#include <QTest>

#include "model/walked_list.h"

using namespace cambench;

namespace {

ListWalk walkOf(std::initializer_list<const char*> keys, bool end = true) {
    ListWalk walk;
    for (const char* key : keys) {
        // A leading '~' marks a step after which an entry may be missing.
        const QString text = QString::fromLatin1(key);
        const bool maySkip = text.startsWith(u'~');
        walk.steps.append({maySkip ? text.mid(1) : text, maySkip});
    }
    walk.reachedEnd = end;
    return walk;
}

// A walk as a device with a cursor makes it on a line that loses replies:
// a step sent twice moves the cursor twice, and the reply that arrives may
// be either one (the late first or the second), so the entries on both
// sides of the reply are marked.
ListWalk simulatedWalk(const QStringList& list, double lossRate, QRandomGenerator& random) {
    ListWalk walk;
    qsizetype cursor = 0;
    bool afterRepeat = false;
    for (int step = 0;; ++step) {
        const bool repeated = step > 0 && random.generateDouble() < lossRate;
        qsizetype shownAt = cursor;
        if (repeated) {
            const bool lateFirstReply = random.generateDouble() < 0.5;
            cursor += 1;  // the second execution
            shownAt = lateFirstReply ? cursor - 1 : cursor;
        }
        const bool maySkip = repeated || afterRepeat;
        afterRepeat = repeated;
        if (shownAt >= list.size()) {
            walk.reachedEnd = true;
            walk.endMaySkip = maySkip;
            return walk;
        }
        walk.steps.append({list.at(shownAt), maySkip});
        ++cursor;
    }
}

}  // namespace

class TestWalkedList : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void oneCleanWalkIsComplete();
    void emptyListIsComplete();
    void walksLosingDifferentStepsAddUpToTheWholeList();
    void aGapNoWalkClosedIsNamed();
    void anEndNeverSeenIsAGap();
    void walksThatDisagreeAreAContradiction();
    void mergedWalksNeverClaimAWrongList();
};

void TestWalkedList::oneCleanWalkIsComplete() {
    const WalkedList merged = mergeWalks({walkOf({"a", "b", "c"})});
    QVERIFY(merged.complete);
    QCOMPARE(merged.keys, (QStringList{"a", "b", "c"}));
}

void TestWalkedList::emptyListIsComplete() {
    const WalkedList merged = mergeWalks({walkOf({})});
    QVERIFY(merged.complete);
    QVERIFY(merged.keys.isEmpty());
}

void TestWalkedList::walksLosingDifferentStepsAddUpToTheWholeList() {
    // The first walk skipped "b" after a repeated step, the second lost its
    // place further on; neither alone is whole, together they are.
    const ListWalk first = walkOf({"a", "~c", "~d", "e"});
    const ListWalk second = walkOf({"a", "b", "c", "~e"});
    QVERIFY(!mergeWalks({first}).complete);
    QVERIFY(!mergeWalks({second}).complete);
    const WalkedList merged = mergeWalks({first, second});
    QVERIFY(!merged.complete);  // c -> d -> e still uncertain: d, e were only seen after a repeat
    const WalkedList whole = mergeWalks({first, second, walkOf({"a", "b", "c", "d", "e"})});
    QVERIFY(whole.complete);
    QCOMPARE(whole.keys, (QStringList{"a", "b", "c", "d", "e"}));
}

void TestWalkedList::aGapNoWalkClosedIsNamed() {
    const WalkedList merged = mergeWalks({walkOf({"a", "~b", "c"}), walkOf({"a", "~b", "c"})});
    QVERIFY(!merged.complete);
    QCOMPARE(merged.keys, (QStringList{"a", "b", "c"}));
    QCOMPARE(merged.uncertainGaps.size(), 1);
    QCOMPARE(merged.uncertainGaps.first(), (QPair<QString, QString>{"a", "b"}));
}

void TestWalkedList::anEndNeverSeenIsAGap() {
    const WalkedList merged = mergeWalks({walkOf({"a", "b"}, false)});
    QVERIFY(!merged.complete);
    QCOMPARE(merged.uncertainGaps.size(), 1);
    QCOMPARE(merged.uncertainGaps.first(), (QPair<QString, QString>{"b", QString()}));
}

void TestWalkedList::walksThatDisagreeAreAContradiction() {
    // Someone added "x" at the keypad between two walks.
    const WalkedList merged = mergeWalks({walkOf({"a", "b"}), walkOf({"a", "x", "b"})});
    QVERIFY(merged.contradicted);
    QVERIFY(!merged.complete);
    QCOMPARE(merged.contradictionAt, QStringLiteral("a"));
}

void TestWalkedList::mergedWalksNeverClaimAWrongList() {
    // Thousands of simulated reads of a 20-entry list, one reply in ten (and
    // one in three) lost: whenever the merge says complete, it is the list;
    // with one in ten, eight walks are enough nearly always.
    QStringList list;
    for (int i = 1; i <= 20; ++i) list.append(QStringLiteral("user %1").arg(i));
    for (const double loss : {0.1, 0.33}) {
        int completeWithinEight = 0;
        for (quint32 seed = 1; seed <= 1000; ++seed) {
            QRandomGenerator random(seed);
            QList<ListWalk> walks;
            for (int walk = 0; walk < 30; ++walk) {
                walks.append(simulatedWalk(list, loss, random));
                const WalkedList merged = mergeWalks(walks);
                QVERIFY(!merged.contradicted);
                if (!merged.complete) continue;
                QCOMPARE(merged.keys, list);
                if (walks.size() <= 8) ++completeWithinEight;
                break;
            }
        }
        if (loss < 0.2)
            QVERIFY2(completeWithinEight >= 995, qPrintable(QString::number(completeWithinEight)));
    }
}

QTEST_GUILESS_MAIN(TestWalkedList)
#include "tst_walked_list.moc"
