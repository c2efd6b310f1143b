// The MC-1's differences item by item: variables, flags, memory ranges.
#include "mc1_backup_restore.h"

#include "comm/mc1/mc1_address.h"

#include <QCoreApplication>

#include <set>

namespace cambench::usecases {

namespace {

QString hex4(int address) {
    return QStringLiteral("0x") +
           QStringLiteral("%1").arg(address, 4, 16, QLatin1Char('0')).toUpper();
}

QString hexBytes(const QByteArray& bytes) {
    return QString::fromLatin1(bytes.toHex(' '));
}

BackupDifference item(const QString& key, ChangeKind kind, const QString& before,
                      const QString& after) {
    return {{},
            key,
            {},
            before,
            after,
            kind,
            QStringLiteral("%1 %2").arg(key, changeText(kind, before, after))};
}

bool flagAt(const QByteArray& page, int bit) {
    return (quint8(page.at(bit >> 3)) >> (bit & 7)) & 1;
}

void diffVariables(const Mc1Backup& before, const Mc1Backup& after, QList<BackupDifference>& out) {
    std::set<int> numbers;
    for (auto it = before.variables.begin(); it != before.variables.end(); ++it)
        numbers.insert(it.key());
    for (auto it = after.variables.begin(); it != after.variables.end(); ++it)
        numbers.insert(it.key());
    for (int number : numbers) {
        const QString key = QStringLiteral("V%1").arg(number);
        const bool inBefore = before.variables.contains(number);
        const bool inAfter = after.variables.contains(number);
        const QString old = QString::number(before.variables.value(number));
        const QString now = QString::number(after.variables.value(number));
        if (!inBefore)
            out << item(key, ChangeKind::Added, {}, now);
        else if (!inAfter)
            out << item(key, ChangeKind::Removed, old, {});
        else if (old != now)
            out << item(key, ChangeKind::Changed, old, now);
    }
}

void diffFlags(const Mc1Backup& before, const Mc1Backup& after, QList<BackupDifference>& out) {
    if (before.flags.isEmpty() && after.flags.isEmpty()) return;
    if (before.flags.isEmpty() || after.flags.isEmpty()) {
        const QString what = QCoreApplication::translate("cambench::usecases", "the flag page");
        out << (before.flags.isEmpty()
                    ? item(what, ChangeKind::Added, {}, QStringLiteral("page"))
                    : item(what, ChangeKind::Removed, QStringLiteral("page"), {}));
        return;
    }
    for (int bit = 0; bit < before.flags.size() * 8 && bit < after.flags.size() * 8; ++bit) {
        const bool old = flagAt(before.flags, bit);
        const bool now = flagAt(after.flags, bit);
        if (old == now) continue;
        out << item(comm::mc1PointText(comm::mc1ExternalFlagAt(bit, before.mc200())),
                    ChangeKind::Changed, old ? QStringLiteral("1") : QStringLiteral("0"),
                    now ? QStringLiteral("1") : QStringLiteral("0"));
    }
}

void diffMemory(const Mc1Backup& before, const Mc1Backup& after, QList<BackupDifference>& out) {
    const auto rangeKey = [](const Mc1MemoryRange& range) {
        return mc1MemoryLabel(range.address, int(range.data.size()));
    };
    const auto find = [](const Mc1Backup& backup, const Mc1MemoryRange& like) {
        for (const Mc1MemoryRange& range : backup.memory)
            if (range.address == like.address && range.data.size() == like.data.size())
                return &range;
        return static_cast<const Mc1MemoryRange*>(nullptr);
    };
    for (const Mc1MemoryRange& range : before.memory) {
        const Mc1MemoryRange* other = find(after, range);
        if (!other) {
            out << item(rangeKey(range), ChangeKind::Removed, QStringLiteral("range"), {});
            continue;
        }
        int differing = 0;
        int first = -1;
        for (int b = 0; b < range.data.size(); ++b) {
            if (range.data.at(b) == other->data.at(b)) continue;
            ++differing;
            if (first < 0) first = b;
        }
        if (differing == 0) continue;
        // The bytes from the first that differs: a person sees where.
        BackupDifference difference =
            item(rangeKey(range), ChangeKind::Changed, hexBytes(range.data.mid(first, 8)),
                 hexBytes(other->data.mid(first, 8)));
        difference.what = hex4(range.address + first);
        difference.text = QCoreApplication::translate("cambench::usecases",
                                                      "%1: %2 bytes differ, from %3: %4 → %5")
                              .arg(rangeKey(range))
                              .arg(differing)
                              .arg(difference.what, difference.oldValue, difference.newValue);
        out << difference;
    }
    for (const Mc1MemoryRange& range : after.memory)
        if (!find(before, range))
            out << item(rangeKey(range), ChangeKind::Added, {}, QStringLiteral("range"));
}

}  // namespace

QString mc1MemoryLabel(int address, int length) {
    return QCoreApplication::translate("cambench::usecases", "memory %1–%2")
        .arg(hex4(address), hex4(address + length - 1));
}

QList<BackupDifference> diffMc1Backups(const Mc1Backup& before, const Mc1Backup& after) {
    QList<BackupDifference> out;
    if (before.variant != after.variant)
        out << item(QCoreApplication::translate("cambench::usecases", "variant"),
                    ChangeKind::Changed, before.variant, after.variant);
    diffVariables(before, after, out);
    diffFlags(before, after, out);
    diffMemory(before, after, out);
    return out;
}

int mc1ItemCount(const Mc1Backup& backup) {
    int count = int(backup.variables.size() + backup.flags.size() * 8);
    for (const Mc1MemoryRange& range : backup.memory) count += int(range.data.size());
    return count;
}

}  // namespace cambench::usecases
