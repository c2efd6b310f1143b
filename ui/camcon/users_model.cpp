#include "users_model.h"

#include "ui/change_marker.h"
#include "workspace.h"

namespace cambench {

UsersModel::UsersModel(Workspace* workspace, QObject* parent)
    : QAbstractTableModel(parent), m_workspace(workspace) {
    connect(workspace, &Workspace::usersChanged, this, &UsersModel::reset);
    m_rows = int(workspace->users().size());
}

void UsersModel::reset() {
    if (m_rows == m_workspace->users().size()) {
        if (m_rows > 0) Q_EMIT dataChanged(index(0, 0), index(m_rows - 1, COUNT - 1));
        return;
    }
    beginResetModel();
    m_rows = int(m_workspace->users().size());
    endResetModel();
}

void UsersModel::revealNumbers(bool reveal) {
    m_reveal = reveal;
    if (m_rows > 0) Q_EMIT dataChanged(index(0, NumberColumn), index(m_rows - 1, NumberColumn));
}

int UsersModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : m_rows;
}

int UsersModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : COUNT;
}

QString UsersModel::rightsText(quint32 rights) {
    QStringList names;
    if (rights & User::ProgramSelection) names << tr("program selection");
    if (rights & User::Programming) names << tr("programming");
    if (rights & User::SystemSettings) names << tr("system settings");
    if (rights & User::DeviceConfiguration) names << tr("configuration");
    if (rights & User::PlcMenu) names << tr("PLC");
    if (rights & User::AllOutputs) names << tr("all outputs");
    if (rights & User::UserMenu) names << tr("users");
    return names.isEmpty() ? tr("none") : names.join(QStringLiteral(", "));
}

QVariant UsersModel::data(const QModelIndex& index, int role) const {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid)) return {};
    const User user = m_workspace->users().row(index.row()).user;
    const bool changed = m_workspace->users().isChanged(index.row());
    if (role == Qt::FontRole && changed) return changedFont();
    if (role == Qt::ToolTipRole && changed) return tr("Edited, not yet written to the device.");
    if (role != Qt::DisplayRole) return {};
    switch (index.column()) {
        case NameColumn:
            return (changed ? changedMarker() : QString()) + user.name;
        case NumberColumn:
            return m_reveal ? user.number : user.maskedNumber();
        case RightsColumn:
            return rightsText(user.rights);
        default:
            return {};
    }
}

QVariant UsersModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
        case NameColumn:
            return tr("Name");
        case NumberColumn:
            return tr("User number");
        case RightsColumn:
            return tr("Rights");
        default:
            return {};
    }
}

}  // namespace cambench
