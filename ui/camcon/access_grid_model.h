#pragma once

#include <QAbstractTableModel>

namespace cambench {

class Workspace;

// The per-output access bits of one user as a grid of 8 outputs per row.
class AccessGridModel : public QAbstractTableModel {
    Q_OBJECT
public:
    static constexpr int kColumns = 8;

    explicit AccessGridModel(Workspace* workspace, QObject* parent = nullptr);

    void setUser(int index);                       // -1 = none
    int outputAt(const QModelIndex& index) const;  // 1-based, 0 outside

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;

private:
    void reset();

    Workspace* m_workspace;
    int m_user = -1;
    int m_rows = 0;
    int m_outputs = 0;
};

}  // namespace cambench
