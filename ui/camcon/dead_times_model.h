#pragma once

#include <QAbstractTableModel>

namespace cambench {

class Workspace;

// Dead time and name per output, beside the device's values. The dead time
// is shown and edited in ms with 0.1 ms steps up to the device's maximum
// (?GTZKMAX); edits go through the cam document's undo stack.
class DeadTimesModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { OutputColumn, NameColumn, DeadTimeColumn, DeviceColumn, COUNT };

    explicit DeadTimesModel(Workspace* workspace, QObject* parent = nullptr);

    static int outputForRow(int row) { return row + 1; }
    bool isChanged(int output) const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    void resetRows();
    void outputChanged(int output);
    QVariant deadTimeData(int output, int role) const;

    Workspace* m_workspace;
    int m_rows = 0;
};

}  // namespace cambench
