#include "dead_times_model.h"

#include "ui/change_marker.h"
#include "workspace.h"

#include "ui/camcon/cameditor/cam_document.h"
#include "ui/camcon/cameditor/editor_roles.h"

#include <QLocale>

namespace cambench {

namespace {
QString milliseconds(qint32 tenths) {
    return QLocale().toString(tenths / 10.0, 'f', 1);
}
}  // namespace

DeadTimesModel::DeadTimesModel(Workspace* workspace, QObject* parent)
    : QAbstractTableModel(parent), m_workspace(workspace) {
    CamDocument* cams = workspace->cams();
    connect(cams, &CamDocument::deadTimeChanged, this, &DeadTimesModel::outputChanged);
    connect(cams, &CamDocument::outputNameChanged, this, &DeadTimesModel::outputChanged);
    connect(cams, &CamDocument::deviceStateChanged, this, [this] {
        if (m_rows > 0) Q_EMIT dataChanged(index(0, 0), index(m_rows - 1, COUNT - 1));
    });
    connect(workspace, &Workspace::infoChanged, this, &DeadTimesModel::resetRows);
    m_rows = m_workspace->info().deadTimeOutputs;
}

void DeadTimesModel::resetRows() {
    beginResetModel();
    m_rows = m_workspace->info().deadTimeOutputs;
    endResetModel();
}

void DeadTimesModel::outputChanged(int output) {
    const int row = output - 1;
    if (row < 0 || row >= m_rows) return;
    Q_EMIT dataChanged(index(row, 0), index(row, COUNT - 1));
}

bool DeadTimesModel::isChanged(int output) const {
    const CamDocument* cams = m_workspace->cams();
    return cams->deadTime(output) != m_workspace->deviceDeadTime(output) ||
           !m_workspace->outputSettingsKnown();
}

int DeadTimesModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : m_rows;
}

int DeadTimesModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : COUNT;
}

QVariant DeadTimesModel::data(const QModelIndex& index, int role) const {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid)) return {};
    const int output = outputForRow(index.row());
    switch (index.column()) {
        case OutputColumn:
            return role == Qt::DisplayRole ? QVariant(output) : QVariant();
        case NameColumn:
            return role == Qt::DisplayRole ? QVariant(m_workspace->cams()->outputName(output))
                                           : QVariant();
        case DeadTimeColumn:
            return deadTimeData(output, role);
        case DeviceColumn:
            if (role == Qt::DisplayRole) {
                return m_workspace->outputSettingsKnown()
                           ? tr("%1 ms").arg(milliseconds(m_workspace->deviceDeadTime(output)))
                           : tr("not read");
            }
            if (role == Qt::TextAlignmentRole)
                return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
            return {};
        default:
            return {};
    }
}

QVariant DeadTimesModel::deadTimeData(int output, int role) const {
    const qint32 tenths = m_workspace->cams()->deadTime(output);
    const bool changed = isChanged(output);
    switch (role) {
        case Qt::DisplayRole:
            return (changed ? changedMarker() : QString()) + tr("%1 ms").arg(milliseconds(tenths));
        case Qt::FontRole:
            return changed ? QVariant(changedFont()) : QVariant();
        case Qt::ToolTipRole:
            return changed ? tr("Edited, not yet written to the device.")
                           : tr("Same as on the device.");
        default:
            return millisecondsEditData(tenths, m_workspace->info().maxDeadTime / 10.0, role);
    }
}

bool DeadTimesModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (role != Qt::EditRole || !checkIndex(index, CheckIndexOption::IndexIsValid) ||
        index.column() != DeadTimeColumn) {
        return false;
    }
    bool ok = false;
    const double ms = value.toDouble(&ok);
    const qint32 tenths = qRound(ms * 10.0);
    if (!ok || tenths < 0 || tenths > m_workspace->info().maxDeadTime) return false;
    const int output = outputForRow(index.row());
    if (tenths != m_workspace->cams()->deadTime(output))
        m_workspace->cams()->setDeadTime(output, tenths);
    return true;
}

Qt::ItemFlags DeadTimesModel::flags(const QModelIndex& index) const {
    Qt::ItemFlags flags = QAbstractTableModel::flags(index);
    if (index.isValid() && index.column() == DeadTimeColumn) flags |= Qt::ItemIsEditable;
    return flags;
}

QVariant DeadTimesModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
        case OutputColumn:
            return tr("Output");
        case NameColumn:
            return tr("Name");
        case DeadTimeColumn:
            return tr("Dead time");
        case DeviceColumn:
            return tr("On the device");
        default:
            return {};
    }
}

}  // namespace cambench
