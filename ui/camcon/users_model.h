#pragma once

#include <QAbstractTableModel>

namespace cambench {

class Workspace;

// The users (key assignment) of the workspace. User numbers are access
// codes: shown as ***** until revealNumbers(true).
class UsersModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { NameColumn, NumberColumn, RightsColumn, COUNT };

    explicit UsersModel(Workspace* workspace, QObject* parent = nullptr);

    void revealNumbers(bool reveal);
    bool numbersRevealed() const { return m_reveal; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    static QString rightsText(quint32 rights);

private:
    void reset();

    Workspace* m_workspace;
    bool m_reveal = false;
    int m_rows = 0;
};

}  // namespace cambench
