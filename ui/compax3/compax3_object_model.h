#pragma once

#include "model/compax3/compax3_dictionary.h"

#include <QDateTime>
#include <QHash>
#include <QStandardItemModel>

#include <optional>

namespace cambench {

// The Objects page's tree: the dictionary's groups, each object a row with
// its value on the drive (when it was read, or stale), and the value a
// person typed that is not on the drive yet. Objects typed in by number
// that the dictionary lacks come under "Other objects".
class Compax3ObjectModel : public QStandardItemModel {
    Q_OBJECT
public:
    enum Column { Object, Name, DriveValue, NewValue, Unit, Range, ColumnCount };
    static constexpr int kIdRole = Qt::UserRole + 1;  // "680.5" on every cell of an object row

    explicit Compax3ObjectModel(QObject* parent = nullptr);

    // Rebuilds the tree; edits and values of objects still in it are kept.
    void setDictionary(const Compax3Dictionary& dictionary);
    // The headers, names and groups again in the language now in use.
    void retranslate() { rebuild(); }
    const Compax3Dictionary& dictionary() const { return m_dictionary; }

    // A value read from the drive, or a refusal (`error`); clears stale.
    void setDriveValue(const Compax3ObjectId& id, const QString& value, const QDateTime& at);
    void setDriveError(const Compax3ObjectId& id, const QString& error);
    // The drive does not have the object (it answered "no such object"):
    // greyed "not on this drive", `answer` in the tooltip.
    void setDriveAbsent(const Compax3ObjectId& id, const QString& answer);
    std::optional<QString> driveValue(const Compax3ObjectId& id) const;
    // The line went: every value read is no longer known to be true.
    void markStale();

    // Typed values not yet on the drive (checked: the wire form). A
    // dictionary loaded later checks them again: one it refuses keeps what
    // was typed and says why in `problem` (and is not written).
    struct Edit {
        QString value;
        QString wire;
        QString problem;
    };
    // "1901.1: …" for each typed value the dictionary in use refuses.
    QStringList editProblems() const;
    const QHash<Compax3ObjectId, Edit>& edits() const { return m_edits; }
    // Checks `typed` against the dictionary; an error leaves the edit as it was.
    Status setEdit(const Compax3ObjectId& id, const QString& typed);
    void clearEdit(const Compax3ObjectId& id);
    void clearEdits();

    // Every readable object of the tree, in its order.
    QList<Compax3ObjectId> readableObjects() const;
    // Adds an object typed in by number (for the raw entry) and returns its row.
    void ensureObject(const Compax3ObjectId& id);
    QModelIndex indexOf(const Compax3ObjectId& id, int column) const;

Q_SIGNALS:
    // An edit typed into the tree was refused (range, type, read-only).
    void editRefused(const QString& message);
    // A value typed into the tree was taken as an edit.
    void editAccepted();
    // edits() changed: one added, changed, written or dropped.
    void editsChanged();

private:
    struct Known {
        std::optional<QString> value;
        QString error;
        QDateTime at;
        bool stale = false;
        bool absent = false;
    };
    void rebuild();
    QList<QStandardItem*> rowFor(const Compax3ObjectInfo& info, bool known);
    void refreshRow(const Compax3ObjectId& id);
    void onItemChanged(QStandardItem* item);

    Compax3Dictionary m_dictionary;
    QList<Compax3ObjectId> m_extra;  // typed in, not in the dictionary
    QHash<Compax3ObjectId, Known> m_known;
    QHash<Compax3ObjectId, Edit> m_edits;
    QHash<Compax3ObjectId, QStandardItem*> m_rows;  // column 0 of each object
    bool m_updating = false;
};

}  // namespace cambench
