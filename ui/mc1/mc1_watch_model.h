#pragma once

#include "model/mc1/mc1_project_file.h"

#include <QAbstractTableModel>
#include <QDateTime>
#include <QList>

#include <optional>

namespace cambench {

// The variables a technician watches on an MC100/MC200: number, a name of
// their own (kept on the PC), the value as last read and whether it is
// still live. The value column is editable: an edit is a request to write
// (writeRequested, with the text exactly as typed), never a change of the
// shown value, which only ever shows what was read - the one copy of each
// value that the Variables and the Trend page show.
class Mc1WatchModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { NumberColumn, NameColumn, ValueColumn, StateColumn, ColumnCount };

    struct Entry {
        int number = 0;
        QString name;
        std::optional<qint64> value;
        bool stale = false;
        QDateTime readAt;
        bool restored = false;  // kept from the last session, not read since
    };

    explicit Mc1WatchModel(QObject* parent = nullptr);

    const QList<Entry>& entries() const { return m_entries; }
    QList<int> numbers() const;
    // Adds first..last (those not watched yet); returns how many were added.
    int addRange(int first, int last);
    // Removes `rows` (the model's own removeRows(row, count) stays usable).
    using QAbstractTableModel::removeRows;
    void removeRows(const QList<int>& rows);
    // Names by number ("12" -> "Feed length"); numbers not watched are added.
    void setNames(const QMap<int, QString>& names);
    // Values read at `at`, in the order of numbers().
    void setValues(const QList<qint64>& values, const QDateTime& at);
    // One value read (after a write).
    void setValue(int number, qint64 value, const QDateTime& at);
    // Every value shown is no longer known to be true; `note` says why
    // ("no answer since 12:03:04", "paused (Back up controller), read ...").
    void markStale(const QString& note = {});
    // The row whose value has an editor open (-1: none): its state says
    // what the controller holds while the editor keeps what was typed.
    void setEditingRow(int row);

    // The watch list as a project file holds it (names, last values; the
    // flags as they were loaded), and replaced by one: values from a file
    // are shown as stale until read.
    Mc1Project toProject(const QString& variant) const;
    void setProject(const Mc1Project& project);
    // The watch list of the last session (numbers and names, no values):
    // shown as restored, not read yet, until read.
    void restore(const Mc1Project& project);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;

Q_SIGNALS:
    void writeRequested(int number, qint64 value, const QString& typed);
    // What was typed is not a whole number: nothing is written.
    void typedInvalid(int number, const QString& typed);
    // Numbers or names changed (kept for the next session).
    void listChanged();
    // Fresh values arrived (for the trend).
    void sampled(const QDateTime& at);

private:
    int rowOf(int number) const;
    QString stateText(const Entry& entry) const;

    QList<Entry> m_entries;
    QList<Mc1NamedValue> m_flags;  // kept from a project file, saved back
    QString m_staleNote;
    int m_editingRow = -1;
};

// "12;Feed length" / "12,Feed length" / "V12,Feed length" lines (a header
// line without a number is skipped); an error names the line.
struct Mc1NameList {
    QMap<int, QString> names;
    QString error;
};
Mc1NameList parseMc1NameList(const QByteArray& csv);

}  // namespace cambench
