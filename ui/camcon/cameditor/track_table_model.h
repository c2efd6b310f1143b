#pragma once

#include <QAbstractTableModel>
#include <QFont>

namespace cambench {

class CamDocument;
enum class ChangeState;

// The outputs 1..N of one program: name, dead time, the user's minimum
// pulse (PC only, for the timing check), number of cams and whether the
// track, name or dead time differs from the device. Name, dead time and minimum pulse are
// editable; name and dead time edits go through the document's undo stack.
class TrackTableModel : public QAbstractTableModel {
    Q_OBJECT

public:
    enum Column {
        OutputColumn,
        NameColumn,
        DeadTimeColumn,
        MinimumPulseColumn,
        CamCountColumn,
        StateColumn,
        COUNT
    };

    explicit TrackTableModel(CamDocument* document, QObject* parent = nullptr);

    void setProgram(int program);
    int program() const { return m_program; }
    static int outputForRow(int row) { return row + 1; }
    static int rowForOutput(int output) { return output - 1; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    void resetRows();
    void outputChanged(int output, Column first, Column last);
    QVariant deadTimeData(int output, int role) const;
    QVariant minimumPulseData(int output, int role) const;
    QVariant stateData(int output, int role) const;
    QString stateText(int output, ChangeState cams, ChangeState name, ChangeState deadTime) const;
    static QFont editedFont();
    QVariant camCountData(int output, int role) const;

    CamDocument* m_document;
    int m_program = 0;
    int m_rows = 0;  // cached so a limits change can be announced as a reset
};

}  // namespace cambench
