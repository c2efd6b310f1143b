#pragma once

#include <QAbstractTableModel>

namespace cambench {

class Workspace;

// The 5 current paths x 6 symbols of one PLC network of the workspace.
// Shows decoded symbols where possible and edits them as hex or decoded
// text (see plcsymbol); a changed symbol is marked against the device copy.
class PlcMatrixModel : public QAbstractTableModel {
    Q_OBJECT
public:
    explicit PlcMatrixModel(Workspace* workspace, QObject* parent = nullptr);

    void setNetwork(int area, int number);
    int area() const { return m_area; }
    int number() const { return m_number; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

Q_SIGNALS:
    // An entry was not taken; `reason` says why and what would be.
    void entryRefused(const QString& reason);

private:
    void refresh();

    Workspace* m_workspace;
    int m_area = 0x08;
    int m_number = 0;
};

}  // namespace cambench
