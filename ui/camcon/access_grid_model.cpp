#include "access_grid_model.h"

#include "workspace.h"

namespace cambench {

namespace {
// The device keeps access bits for 256 outputs (notes 4).
constexpr int kAccessBits = 256;
}  // namespace

AccessGridModel::AccessGridModel(Workspace* workspace, QObject* parent)
    : QAbstractTableModel(parent), m_workspace(workspace) {
    connect(workspace, &Workspace::usersChanged, this, &AccessGridModel::reset);
    connect(workspace, &Workspace::infoChanged, this, &AccessGridModel::reset);
    reset();
}

void AccessGridModel::setUser(int index) {
    m_user = index;
    reset();
}

void AccessGridModel::reset() {
    const bool valid = m_user >= 0 && m_user < m_workspace->users().size();
    const int outputs = valid ? std::min(m_workspace->info().outputs, kAccessBits) : 0;
    const int rows = (outputs + kColumns - 1) / kColumns;
    if (rows == m_rows && outputs == m_outputs) {
        if (m_rows > 0) Q_EMIT dataChanged(index(0, 0), index(m_rows - 1, kColumns - 1));
        return;
    }
    beginResetModel();
    m_rows = rows;
    m_outputs = outputs;
    endResetModel();
}

int AccessGridModel::outputAt(const QModelIndex& index) const {
    const int output = index.row() * kColumns + index.column() + 1;
    return output <= m_outputs ? output : 0;
}

int AccessGridModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : m_rows;
}

int AccessGridModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() || m_rows == 0 ? 0 : kColumns;
}

QVariant AccessGridModel::data(const QModelIndex& index, int role) const {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid)) return {};
    const int output = outputAt(index);
    if (output == 0) return {};
    const User user = m_workspace->users().row(m_user).user;
    switch (role) {
        case Qt::DisplayRole:
            return output;
        case Qt::CheckStateRole:
            return (user.allOutputs || user.outputAccess.value(output - 1)) ? Qt::Checked
                                                                            : Qt::Unchecked;
        case Qt::ToolTipRole:
            return user.allOutputs
                       ? tr("Output %1: allowed (the user may change all outputs)").arg(output)
                       : tr("Output %1").arg(output);
        default:
            return {};
    }
}

bool AccessGridModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (role != Qt::CheckStateRole || !checkIndex(index, CheckIndexOption::IndexIsValid))
        return false;
    const int output = outputAt(index);
    if (output == 0) return false;
    User user = m_workspace->users().row(m_user).user;
    if (user.outputAccess.size() < kAccessBits) user.outputAccess.resize(kAccessBits);
    user.outputAccess[output - 1] = value.toInt() == Qt::Checked;
    m_workspace->users().set(m_user, user);
    return true;
}

Qt::ItemFlags AccessGridModel::flags(const QModelIndex& index) const {
    if (!index.isValid() || outputAt(index) == 0) return Qt::NoItemFlags;
    const bool all = m_workspace->users().row(m_user).user.allOutputs;
    return Qt::ItemIsEnabled | Qt::ItemIsSelectable |
           (all ? Qt::NoItemFlags : Qt::ItemIsUserCheckable);
}

}  // namespace cambench
