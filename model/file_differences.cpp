#include "file_differences.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <vector>

namespace cambench {

namespace {

// Longer strings (EEPROM blocks in hex) are shown around where they differ.
constexpr int kShortString = 48;
constexpr int kAround = 16;
// Above this many line pairs the middle of two texts is shown as replaced
// as a whole rather than matched line by line (the table would not fit).
constexpr qsizetype kMostCells = 4'000'000;

QString compact(const QJsonValue& value) {
    if (value.isString()) return QStringLiteral("\"%1\"").arg(value.toString());
    if (value.isObject())
        return QString::fromUtf8(QJsonDocument(value.toObject()).toJson(QJsonDocument::Compact));
    if (value.isArray())
        return QString::fromUtf8(QJsonDocument(value.toArray()).toJson(QJsonDocument::Compact));
    // A scalar: through an array, the one way QJsonDocument writes it.
    const QByteArray json = QJsonDocument(QJsonArray{value}).toJson(QJsonDocument::Compact);
    return QString::fromUtf8(json.mid(1, json.size() - 2));
}

QString shown(const QJsonValue& value) {
    const QString text = compact(value);
    return text.size() <= 2 * kShortString ? text : text.left(2 * kShortString) + u'…';
}

QString stringChange(const QString& a, const QString& b) {
    if (a.size() <= kShortString && b.size() <= kShortString)
        return QStringLiteral("\"%1\" → \"%2\"").arg(a, b);
    qsizetype at = 0;
    while (at < a.size() && at < b.size() && a.at(at) == b.at(at)) ++at;
    const qsizetype from = std::max<qsizetype>(0, at - kAround);
    return QStringLiteral("differs from character %1: …%2… → …%3…")
        .arg(at + 1)
        .arg(a.mid(from, 2 * kAround), b.mid(from, 2 * kAround));
}

QString member(const QString& path, const QString& key) {
    return path.isEmpty() ? key : path + u'.' + key;
}

void differences(const QJsonValue& a, const QJsonValue& b, const QString& path,
                 const QStringList& skipped, QStringList& lines) {
    if (a == b) return;
    const QString where = path.isEmpty() ? QStringLiteral("(whole file)") : path;
    if (a.isObject() && b.isObject()) {
        const QJsonObject oa = a.toObject();
        const QJsonObject ob = b.toObject();
        QStringList keys = oa.keys() + ob.keys();
        std::sort(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
        for (const QString& key : keys) {
            if (path.isEmpty() && skipped.contains(key)) continue;
            const QString at = member(path, key);
            if (!oa.contains(key))
                lines << QStringLiteral("%1: only in B: %2").arg(at, shown(ob.value(key)));
            else if (!ob.contains(key))
                lines << QStringLiteral("%1: only in A: %2").arg(at, shown(oa.value(key)));
            else
                differences(oa.value(key), ob.value(key), at, {}, lines);
        }
        return;
    }
    if (a.isArray() && b.isArray()) {
        const QJsonArray aa = a.toArray();
        const QJsonArray ab = b.toArray();
        for (qsizetype i = 0; i < std::max(aa.size(), ab.size()); ++i) {
            const QString at = QStringLiteral("%1[%2]").arg(path).arg(i);
            if (i >= aa.size())
                lines << QStringLiteral("%1: only in B: %2").arg(at, shown(ab.at(i)));
            else if (i >= ab.size())
                lines << QStringLiteral("%1: only in A: %2").arg(at, shown(aa.at(i)));
            else
                differences(aa.at(i), ab.at(i), at, {}, lines);
        }
        return;
    }
    if (a.isString() && b.isString()) {
        lines << QStringLiteral("%1: %2").arg(where, stringChange(a.toString(), b.toString()));
        return;
    }
    lines << QStringLiteral("%1: %2 → %3").arg(where, shown(a), shown(b));
}

// One step of the way from A's lines to B's.
enum class Step { Same, Removed, Added };

// The steps of a longest common subsequence of a and b (a table of
// a.size() x b.size(); the caller keeps it small).
std::vector<Step> lcsSteps(const QStringList& a, const QStringList& b) {
    const size_t n = size_t(a.size());
    const size_t m = size_t(b.size());
    std::vector<std::vector<int>> common(n + 1, std::vector<int>(m + 1, 0));
    for (size_t i = n; i-- > 0;)
        for (size_t j = m; j-- > 0;)
            common[i][j] = a.at(qsizetype(i)) == b.at(qsizetype(j))
                               ? common[i + 1][j + 1] + 1
                               : std::max(common[i + 1][j], common[i][j + 1]);
    std::vector<Step> steps;
    size_t i = 0;
    size_t j = 0;
    while (i < n || j < m) {
        if (i < n && j < m && a.at(qsizetype(i)) == b.at(qsizetype(j))) {
            steps.push_back(Step::Same);
            ++i;
            ++j;
        } else if (j < m && (i == n || common[i][j + 1] >= common[i + 1][j])) {
            steps.push_back(Step::Added);
            ++j;
        } else {
            steps.push_back(Step::Removed);
            ++i;
        }
    }
    return steps;
}

}  // namespace

QStringList jsonDifferences(const QJsonValue& a, const QJsonValue& b, const QStringList& skipped) {
    QStringList lines;
    differences(a, b, {}, skipped, lines);
    return lines;
}

QString textDifferences(const QString& a, const QString& b) {
    if (a == b) return {};
    QStringList la = a.split(u'\n');
    QStringList lb = b.split(u'\n');
    // The common start and end are left out of the table.
    qsizetype head = 0;
    while (head < la.size() && head < lb.size() && la.at(head) == lb.at(head)) ++head;
    qsizetype tail = 0;
    while (tail < la.size() - head && tail < lb.size() - head &&
           la.at(la.size() - 1 - tail) == lb.at(lb.size() - 1 - tail))
        ++tail;
    const QStringList ma = la.mid(head, la.size() - head - tail);
    const QStringList mb = lb.mid(head, lb.size() - head - tail);
    std::vector<Step> steps;
    if (ma.size() * mb.size() <= kMostCells) {
        steps = lcsSteps(ma, mb);
    } else {
        steps.assign(size_t(ma.size()), Step::Removed);
        steps.insert(steps.end(), size_t(mb.size()), Step::Added);
    }
    QString text;
    qsizetype ia = 0;
    qsizetype ib = 0;
    for (size_t s = 0; s < steps.size();) {
        if (steps[s] == Step::Same) {
            ++ia;
            ++ib;
            ++s;
            continue;
        }
        // A run of changes: its removed lines, then its added ones.
        QStringList removed;
        QStringList added;
        const qsizetype startA = ia;
        const qsizetype startB = ib;
        for (; s < steps.size() && steps[s] != Step::Same; ++s) {
            if (steps[s] == Step::Removed)
                removed << ma.at(ia++);
            else
                added << mb.at(ib++);
        }
        text += QStringLiteral("@@ -%1,%2 +%3,%4 @@\n")
                    .arg(head + startA + 1)
                    .arg(removed.size())
                    .arg(head + startB + 1)
                    .arg(added.size());
        for (const QString& line : removed) text += u'-' + line + u'\n';
        for (const QString& line : added) text += u'+' + line + u'\n';
    }
    return text;
}

}  // namespace cambench
