#include "compax3_object_model.h"

#include "ui/change_marker.h"
#include "ui/language.h"

#include <QBrush>
#include <QFont>
#include <QRegularExpression>

namespace cambench {

namespace {

// Sets `role` only when it changes: QStandardItem reports even an unset
// role cleared again as a change, and a change of a cell with an open
// editor puts the model's text back into it (what is typed must stay).
void setRole(QStandardItem* item, int role, const QVariant& value) {
    if (item->data(role) != value) item->setData(value, role);
}

// The dictionary names the drive's user unit in English ("unit/s²"): said
// in the person's language ("Einheit/s²").
QString shownUnit(const QString& unit) {
    static const QRegularExpression word(QStringLiteral("\\bunit\\b"));
    return QString(unit).replace(word, Compax3ObjectModel::tr("unit"));
}

}  // namespace

Compax3ObjectModel::Compax3ObjectModel(QObject* parent) : QStandardItemModel(parent) {
    connect(this, &QStandardItemModel::itemChanged, this, &Compax3ObjectModel::onItemChanged);
}

void Compax3ObjectModel::setDictionary(const Compax3Dictionary& dictionary) {
    m_dictionary = dictionary;
    // Typed values of objects the new dictionary lacks stay, by number.
    for (auto it = m_edits.cbegin(); it != m_edits.cend(); ++it)
        if (!m_dictionary.find(it.key()) && !m_extra.contains(it.key())) m_extra << it.key();
    // Every typed value checked again against the new dictionary's type
    // and range; a refused one stays typed in, marked, and is not written.
    for (auto it = m_edits.begin(); it != m_edits.end(); ++it) {
        const Result<QString> wire = compax3WireValueFor(m_dictionary, it.key(), it->value);
        it->wire = wire ? *wire : QString();
        it->problem = wire ? QString() : wire.error().message;
    }
    rebuild();
}

QList<QStandardItem*> Compax3ObjectModel::rowFor(const Compax3ObjectInfo& info, bool known) {
    QList<QStandardItem*> row;
    for (int column = 0; column < ColumnCount; ++column) {
        auto* item = new QStandardItem;
        item->setEditable(column == NewValue && info.writable());
        item->setData(info.id.text(), kIdRole);
        row << item;
    }
    row[Object]->setText(info.id.text());
    const QString language = currentLanguage();
    row[Name]->setText(known ? info.nameIn(language) : tr("(not in the dictionary)"));
    row[Unit]->setText(shownUnit(info.unit));
    QString range = info.range.text();
    if (info.access == Compax3Access::ReadOnly) range = tr("read-only");
    if (info.access == Compax3Access::WriteOnly) range = tr("function (written only)");
    if (info.access == Compax3Access::Command) range = tr("control word: Motion page");
    row[Range]->setText(range);
    row[Name]->setToolTip(info.helpIn(language));
    if (info.access == Compax3Access::Command) row[NewValue]->setEditable(false);
    m_rows.insert(info.id, row[Object]);
    return row;
}

void Compax3ObjectModel::rebuild() {
    m_updating = true;
    clear();
    m_rows.clear();
    setHorizontalHeaderLabels(
        {tr("Object"), tr("Name"), tr("On the drive"), tr("New value"), tr("Unit"), tr("Range")});
    QHash<QString, QStandardItem*> groups;
    for (const Compax3ObjectInfo& info : m_dictionary.objects()) {
        QStandardItem*& group = groups[info.group];
        if (!group) {
            group = new QStandardItem(info.groupIn(currentLanguage()));
            group->setEditable(false);
            QList<QStandardItem*> groupRow{group};
            for (int column = 1; column < ColumnCount; ++column) {
                auto* filler = new QStandardItem;
                filler->setEditable(false);
                groupRow << filler;
            }
            appendRow(groupRow);
        }
        group->appendRow(rowFor(info, true));
    }
    if (!m_extra.isEmpty()) {
        auto* other = new QStandardItem(tr("Other objects"));
        other->setEditable(false);
        appendRow(other);
        for (const Compax3ObjectId& id : m_extra) {
            Compax3ObjectInfo info;
            info.id = id;
            info.type = Compax3Type::Real;
            other->appendRow(rowFor(info, false));
        }
    }
    m_updating = false;
    for (auto it = m_rows.cbegin(); it != m_rows.cend(); ++it) refreshRow(it.key());
}

void Compax3ObjectModel::ensureObject(const Compax3ObjectId& id) {
    if (m_rows.contains(id)) return;
    m_extra << id;
    rebuild();
}

QModelIndex Compax3ObjectModel::indexOf(const Compax3ObjectId& id, int column) const {
    QStandardItem* first = m_rows.value(id);
    if (!first) return {};
    return first->index().siblingAtColumn(column);
}

void Compax3ObjectModel::refreshRow(const Compax3ObjectId& id) {
    QStandardItem* first = m_rows.value(id);
    if (!first) return;
    QStandardItem* parent = first->parent();
    QStandardItem* value = parent->child(first->row(), DriveValue);
    QStandardItem* edit = parent->child(first->row(), NewValue);
    m_updating = true;
    const Known known = m_known.value(id);
    for (QStandardItem* cell : {first, parent->child(first->row(), Name)})
        setRole(cell, Qt::ForegroundRole, known.absent ? QVariant(QBrush(Qt::gray)) : QVariant());
    if (known.absent) {
        value->setText(tr("not on this drive"));
        value->setToolTip(tr("The drive does not have this object: %1").arg(known.error));
        value->setForeground(QBrush(Qt::gray));
        QFont font = value->font();
        font.setItalic(true);
        value->setFont(font);
    } else if (!known.error.isEmpty()) {
        value->setText(tr("refused"));
        value->setToolTip(known.error);
        value->setForeground(QBrush(QColor(0xd0, 0x30, 0x30)));
    } else if (known.value) {
        value->setText(*known.value);
        value->setToolTip(known.stale
                              ? tr("Stale: read %1, the connection was lost since.")
                                    .arg(known.at.toString(QStringLiteral("HH:mm:ss")))
                              : tr("Read %1.").arg(known.at.toString(QStringLiteral("HH:mm:ss"))));
        // No colour of its own unless stale: the palette's text colour.
        setRole(value, Qt::ForegroundRole, known.stale ? QVariant(QBrush(Qt::gray)) : QVariant());
        QFont font = value->font();
        font.setItalic(known.stale);
        value->setFont(font);
    } else {
        value->setText(QString());
        value->setToolTip(tr("Not read yet."));
    }
    const auto it = m_edits.constFind(id);
    const bool edited = it != m_edits.cend();
    // The house marker of an edit not on the device: a dot and bold.
    first->setText(edited ? changedMarker() + id.text() : id.text());
    for (QStandardItem* cell : {first, edit}) {
        QFont font = cell->font();
        font.setBold(edited);
        cell->setFont(font);
    }
    if (edited) {
        edit->setText(it->value);
        edit->setToolTip(
            it->problem.isEmpty()
                ? tr("Edited on this PC, not on the drive yet: Write changes sends it.")
                : tr("Typed in, but the dictionary in use refuses it: %1").arg(it->problem));
        setRole(edit, Qt::ForegroundRole,
                it->problem.isEmpty() ? QVariant() : QVariant(QBrush(QColor(0xd0, 0x30, 0x30))));
    } else {
        edit->setText(QString());
        edit->setToolTip(edit->isEditable() ? tr("Type a new value (decimal point: 12.5)")
                                            : QString());
        setRole(edit, Qt::ForegroundRole, QVariant());
    }
    m_updating = false;
}

void Compax3ObjectModel::setDriveValue(const Compax3ObjectId& id, const QString& value,
                                       const QDateTime& at) {
    m_known.insert(id, Known{value, {}, at, false});
    refreshRow(id);
}

void Compax3ObjectModel::setDriveError(const Compax3ObjectId& id, const QString& error) {
    m_known.insert(id, Known{std::nullopt, error, QDateTime::currentDateTime(), false});
    refreshRow(id);
}

void Compax3ObjectModel::setDriveAbsent(const Compax3ObjectId& id, const QString& answer) {
    m_known.insert(id, Known{std::nullopt, answer, QDateTime::currentDateTime(), false, true});
    refreshRow(id);
}

QStringList Compax3ObjectModel::editProblems() const {
    QStringList problems;
    for (auto it = m_edits.cbegin(); it != m_edits.cend(); ++it)
        if (!it->problem.isEmpty()) problems << it->problem;
    problems.sort();
    return problems;
}

std::optional<QString> Compax3ObjectModel::driveValue(const Compax3ObjectId& id) const {
    return m_known.value(id).value;
}

void Compax3ObjectModel::markStale() {
    for (auto it = m_known.begin(); it != m_known.end(); ++it) {
        it->stale = true;
        refreshRow(it.key());
    }
}

Status Compax3ObjectModel::setEdit(const Compax3ObjectId& id, const QString& typed) {
    const Result<QString> wire = compax3WireValueFor(m_dictionary, id, typed);
    if (!wire) return wire.error();
    m_edits.insert(id, Edit{typed.trimmed(), *wire, {}});
    refreshRow(id);
    Q_EMIT editsChanged();
    return success();
}

void Compax3ObjectModel::clearEdit(const Compax3ObjectId& id) {
    if (!m_edits.remove(id)) return;
    refreshRow(id);
    Q_EMIT editsChanged();
}

void Compax3ObjectModel::clearEdits() {
    const QList<Compax3ObjectId> ids = m_edits.keys();
    m_edits.clear();
    for (const Compax3ObjectId& id : ids) refreshRow(id);
    if (!ids.isEmpty()) Q_EMIT editsChanged();
}

QList<Compax3ObjectId> Compax3ObjectModel::readableObjects() const {
    QList<Compax3ObjectId> ids;
    for (const Compax3ObjectInfo& info : m_dictionary.objects())
        if (info.readable()) ids << info.id;
    ids << m_extra;
    return ids;
}

void Compax3ObjectModel::onItemChanged(QStandardItem* item) {
    if (m_updating || item->column() != NewValue) return;
    const Result<Compax3ObjectId> id = parseCompax3Object(item->data(kIdRole).toString());
    if (!id) return;
    const QString typed = item->text();
    if (typed.trimmed().isEmpty()) {
        clearEdit(*id);
        return;
    }
    if (const Status set = setEdit(*id, typed); !set) {
        refreshRow(*id);  // back to what it was
        Q_EMIT editRefused(set.error().message);
        return;
    }
    Q_EMIT editAccepted();
}

}  // namespace cambench
