#include "volatile_items.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <optional>

namespace cambench {

namespace {

QString tr(const char* text) {
    return QCoreApplication::translate("cambench::model", text);
}

// "V100-V199" or "V100-199": the text before the number, and both ends.
struct KeyRange {
    QString prefix;
    qint64 first = 0;
    qint64 last = 0;
};

std::optional<KeyRange> rangeOf(const QString& item) {
    static const QRegularExpression range(QStringLiteral("^(.*?)(\\d+)-(.*?)(\\d+)$"));
    const QRegularExpressionMatch match = range.match(item);
    if (!match.hasMatch()) return std::nullopt;
    if (!match.captured(3).isEmpty() && match.captured(3) != match.captured(1)) return std::nullopt;
    return KeyRange{match.captured(1), match.captured(2).toLongLong(),
                    match.captured(4).toLongLong()};
}

}  // namespace

bool isVolatileItem(const QStringList& items, const QString& key) {
    for (const QString& item : items) {
        if (item == key) return true;
        const std::optional<KeyRange> range = rangeOf(item);
        if (!range || !key.startsWith(range->prefix)) continue;
        const QString digits = key.mid(range->prefix.size());
        bool number = !digits.isEmpty();
        for (const QChar c : digits) number = number && c.isDigit();
        if (!number) continue;
        const qint64 value = digits.toLongLong();
        if (value >= range->first && value <= range->last) return true;
    }
    return false;
}

Status checkVolatileItems(const QStringList& items, const QString& where) {
    for (const QString& item : items) {
        if (item.trimmed().isEmpty())
            return Error::invalidData(
                tr("%1: \"volatile\" holds an empty item; name items as a comparison names "
                   "them (\"V12\") or a range (\"V100-V199\").")
                    .arg(where));
        const std::optional<KeyRange> range = rangeOf(item);
        if (range && range->last < range->first)
            return Error::invalidData(
                tr("%1: the volatile range \"%2\" ends below its start; write it low to high.")
                    .arg(where, item));
    }
    return success();
}

}  // namespace cambench
