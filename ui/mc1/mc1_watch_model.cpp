#include "mc1_watch_model.h"

#include <QBrush>
#include <QGuiApplication>
#include <QPalette>
#include <QRegularExpression>

namespace cambench {

Mc1WatchModel::Mc1WatchModel(QObject* parent) : QAbstractTableModel(parent) {}

QList<int> Mc1WatchModel::numbers() const {
    QList<int> numbers;
    for (const Entry& entry : m_entries) numbers << entry.number;
    return numbers;
}

int Mc1WatchModel::rowOf(int number) const {
    for (int row = 0; row < m_entries.size(); ++row)
        if (m_entries.at(row).number == number) return row;
    return -1;
}

int Mc1WatchModel::addRange(int first, int last) {
    QList<int> added;
    for (int n = first; n <= last; ++n)
        if (rowOf(n) < 0) added << n;
    if (added.isEmpty()) return 0;
    beginInsertRows({}, int(m_entries.size()), int(m_entries.size() + added.size() - 1));
    for (int n : added) m_entries << Entry{n, {}, std::nullopt, false, {}, false};
    endInsertRows();
    Q_EMIT listChanged();
    return int(added.size());
}

void Mc1WatchModel::removeRows(const QList<int>& rows) {
    QList<int> sorted = rows;
    std::sort(sorted.begin(), sorted.end(), std::greater<int>());
    for (int row : sorted) {
        if (row < 0 || row >= m_entries.size()) continue;
        beginRemoveRows({}, row, row);
        m_entries.removeAt(row);
        endRemoveRows();
    }
    if (m_editingRow >= m_entries.size()) m_editingRow = -1;
    Q_EMIT listChanged();
}

void Mc1WatchModel::setNames(const QMap<int, QString>& names) {
    for (auto it = names.begin(); it != names.end(); ++it) {
        addRange(it.key(), it.key());
        const int row = rowOf(it.key());
        m_entries[row].name = it.value();
        Q_EMIT dataChanged(index(row, NameColumn), index(row, NameColumn));
    }
    Q_EMIT listChanged();
}

void Mc1WatchModel::setValues(const QList<qint64>& values, const QDateTime& at) {
    for (int row = 0; row < m_entries.size() && row < values.size(); ++row) {
        m_entries[row].value = values.at(row);
        m_entries[row].stale = false;
        m_entries[row].readAt = at;
        m_entries[row].restored = false;
    }
    if (!m_entries.isEmpty())
        Q_EMIT dataChanged(index(0, ValueColumn), index(rowCount() - 1, StateColumn));
    Q_EMIT sampled(at);
}

void Mc1WatchModel::setValue(int number, qint64 value, const QDateTime& at) {
    const int row = rowOf(number);
    if (row < 0) return;
    m_entries[row].value = value;
    m_entries[row].stale = false;
    m_entries[row].readAt = at;
    m_entries[row].restored = false;
    // No trend sample: the other values were not read at `at`; the next
    // poll draws this one with them.
    Q_EMIT dataChanged(index(row, ValueColumn), index(row, StateColumn));
}

void Mc1WatchModel::markStale(const QString& note) {
    bool changed = note != m_staleNote;
    m_staleNote = note;
    for (Entry& entry : m_entries) {
        if (entry.value && !entry.stale) entry.stale = changed = true;
    }
    if (changed && !m_entries.isEmpty())
        Q_EMIT dataChanged(index(0, ValueColumn), index(rowCount() - 1, StateColumn));
}

void Mc1WatchModel::setEditingRow(int row) {
    const int old = m_editingRow;
    m_editingRow = row;
    for (int r : {old, row})
        if (r >= 0 && r < m_entries.size())
            Q_EMIT dataChanged(index(r, StateColumn), index(r, StateColumn));
}

Mc1Project Mc1WatchModel::toProject(const QString& variant) const {
    Mc1Project project;
    project.variant = variant;
    for (const Entry& entry : m_entries)
        project.variables << Mc1NamedValue{QStringLiteral("V%1").arg(entry.number), entry.name,
                                           entry.value};
    project.flags = m_flags;
    return project;
}

void Mc1WatchModel::setProject(const Mc1Project& project) {
    beginResetModel();
    m_entries.clear();
    for (const Mc1NamedValue& variable : project.variables) {
        Entry entry;
        entry.number = variable.point.mid(1).toInt();
        entry.name = variable.name;
        entry.value = variable.value;
        entry.stale = variable.value.has_value();  // from the file, not from the controller
        m_entries << entry;
    }
    m_flags = project.flags;
    m_editingRow = -1;
    endResetModel();
    Q_EMIT listChanged();
}

void Mc1WatchModel::restore(const Mc1Project& project) {
    Mc1Project names = project;
    for (Mc1NamedValue& variable : names.variables) variable.value.reset();
    setProject(names);
    for (Entry& entry : m_entries) entry.restored = true;
    if (!m_entries.isEmpty())
        Q_EMIT dataChanged(index(0, StateColumn), index(rowCount() - 1, StateColumn));
}

QString Mc1WatchModel::stateText(const Entry& entry) const {
    if (!entry.value)
        return entry.restored ? tr("restored from last session, not read yet") : tr("not read");
    if (entry.stale && !entry.readAt.isValid()) return tr("from the file, not read");
    if (!entry.stale) return tr("live");
    return m_staleNote.isEmpty()
               ? tr("stale, read %1").arg(entry.readAt.toString(QStringLiteral("HH:mm:ss")))
               : m_staleNote;
}

int Mc1WatchModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_entries.size());
}

int Mc1WatchModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant Mc1WatchModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= m_entries.size()) return {};
    const Entry& entry = m_entries.at(index.row());
    if (role == Qt::DisplayRole || role == Qt::EditRole) {
        switch (index.column()) {
            case NumberColumn:
                return QStringLiteral("V%1").arg(entry.number);
            case NameColumn:
                return entry.name;
            case ValueColumn:
                if (role == Qt::EditRole) return entry.value ? *entry.value : 0;
                return entry.value ? QString::number(*entry.value) : QStringLiteral("—");
            case StateColumn:
                // Beside an open editor: what the controller holds now,
                // while the editor keeps what was typed.
                if (index.row() == m_editingRow && entry.value)
                    return tr("on the controller: %1 (%2)").arg(*entry.value).arg(stateText(entry));
                return stateText(entry);
        }
    }
    if (role == Qt::ForegroundRole && entry.stale &&
        (index.column() == ValueColumn || index.column() == StateColumn))
        return QGuiApplication::palette().brush(QPalette::Disabled, QPalette::Text);
    if (role == Qt::TextAlignmentRole && index.column() == ValueColumn)
        return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::ToolTipRole && index.column() == ValueColumn)
        return tr("Double-click to write a new value to the controller (it asks first).");
    return {};
}

QVariant Mc1WatchModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
        case NumberColumn:
            return tr("Variable");
        case NameColumn:
            return tr("Name (on this PC)");
        case ValueColumn:
            return tr("Value");
        case StateColumn:
            return tr("State");
    }
    return {};
}

Qt::ItemFlags Mc1WatchModel::flags(const QModelIndex& index) const {
    Qt::ItemFlags flags = QAbstractTableModel::flags(index);
    if (index.column() == NameColumn || index.column() == ValueColumn) flags |= Qt::ItemIsEditable;
    return flags;
}

bool Mc1WatchModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || role != Qt::EditRole) return false;
    Entry& entry = m_entries[index.row()];
    if (index.column() == NameColumn) {
        entry.name = value.toString().trimmed();
        Q_EMIT dataChanged(index, index);
        Q_EMIT listChanged();
        return true;
    }
    if (index.column() == ValueColumn) {
        const QString typed = value.toString().trimmed();
        if (typed.isEmpty()) return false;  // nothing typed: nothing to write
        bool ok = false;
        const qint64 wanted = typed.toLongLong(&ok);
        if (!ok)
            Q_EMIT typedInvalid(entry.number, typed);
        else if (!entry.value || wanted != *entry.value)
            Q_EMIT writeRequested(entry.number, wanted, typed);
        return false;  // the shown value stays what was read
    }
    return false;
}

Mc1NameList parseMc1NameList(const QByteArray& csv) {
    Mc1NameList list;
    static const QRegularExpression line(
        QStringLiteral("^\\s*[Vv]?(\\d{1,5})\\s*[;,\\t]\\s*\"?([^\"]*)\"?\\s*$"));
    const QList<QByteArray> lines = csv.split('\n');
    for (int i = 0; i < lines.size(); ++i) {
        const QString text = QString::fromUtf8(lines.at(i)).trimmed();
        if (text.isEmpty()) continue;
        const QRegularExpressionMatch match = line.match(text);
        if (!match.hasMatch()) {
            if (i == 0) continue;  // a header
            list.error = QCoreApplication::translate("cambench::Mc1WatchModel",
                                                     "line %1: \"%2\" is not \"number;name\"")
                             .arg(i + 1)
                             .arg(text.left(40));
            return list;
        }
        const int number = match.captured(1).toInt();
        if (number > 0xFFFF) {
            list.error = QCoreApplication::translate("cambench::Mc1WatchModel",
                                                     "line %1: variable numbers end at 65535")
                             .arg(i + 1);
            return list;
        }
        list.names.insert(number, match.captured(2).trimmed());
    }
    return list;
}

}  // namespace cambench
