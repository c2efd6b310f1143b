#include "ui/camcon/cameditor/cam_table_model.h"

#include "ui/camcon/cameditor/cam_commands.h"
#include "ui/camcon/cameditor/cam_document.h"
#include "ui/camcon/cameditor/editor_colors.h"
#include "ui/camcon/cameditor/editor_roles.h"

#include <QBrush>
#include <QFont>

#include <algorithm>

namespace cambench {

CamTableModel::CamTableModel(CamDocument* document, QObject* parent)
    : QAbstractTableModel(parent), m_document(document) {
    connect(document, &CamDocument::trackChanged, this, [this](int program, int output) {
        if (program == m_program && output == m_output) {
            reload();
        }
    });
    connect(document, &CamDocument::programChanged, this, [this](int program) {
        if (program == m_program) {
            reload();
        }
    });
    connect(document, &CamDocument::limitsChanged, this, &CamTableModel::reload);
    connect(document, &CamDocument::deviceStateChanged, this, &CamTableModel::reload);
    reload();
}

void CamTableModel::setTrack(int program, int output) {
    if (program == m_program && output == m_output) {
        return;
    }
    m_program = program;
    m_output = output;
    reload();
}

void CamTableModel::reload() {
    const Track track = m_document->track(m_program, m_output);
    if (track.cams.size() != m_cams.size()) {
        beginResetModel();
        m_cams = track.cams;
        m_problems = m_document->problems(m_program, m_output);
        endResetModel();
        return;
    }
    // Same number of rows: keep the view's current cell and selection.
    m_cams = track.cams;
    m_problems = m_document->problems(m_program, m_output);
    if (!m_cams.isEmpty()) {
        Q_EMIT dataChanged(index(0, 0), index(int(m_cams.size()) - 1, COUNT - 1));
        Q_EMIT headerDataChanged(Qt::Vertical, 0, int(m_cams.size()) - 1);
    }
}

int CamTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_cams.size());
}

int CamTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : COUNT;
}

const CamProblem* CamTableModel::problemAt(int row) const {
    const auto it = std::find_if(m_problems.cbegin(), m_problems.cend(),
                                 [row](const CamProblem& problem) { return problem.cam == row; });
    return it == m_problems.cend() ? nullptr : &*it;
}

QVariant CamTableModel::data(const QModelIndex& index, int role) const {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid)) {
        return {};
    }
    const Cam& cam = m_cams.at(index.row());
    const CamProblem* problem = problemAt(index.row());
    switch (role) {
        case Qt::BackgroundRole:
            return problem ? QVariant(QBrush(errorColor())) : QVariant();
        case Qt::ForegroundRole:
            return problem ? QVariant(QBrush(Qt::white)) : QVariant();
        case Qt::ToolTipRole:
        case Qt::StatusTipRole:
            return problem ? QVariant(problem->message) : QVariant();
        case Qt::FontRole:
            if (m_document->camState(m_program, m_output, index.row()) == ChangeState::Edited) {
                QFont font;
                font.setBold(true);
                return font;
            }
            return {};
        case Qt::TextAlignmentRole:
            return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
        default:
            return valueData(cam, index.column(), role);
    }
}

QVariant CamTableModel::valueData(const Cam& cam, int column, int role) const {
    const Axis axis = m_document->axis();
    if (role == Qt::DisplayRole || role == Qt::EditRole) {
        switch (column) {
            case OnColumn:
                return cam.on;
            case OffColumn:
                return cam.off;
            case LengthColumn:
                return axis.length(cam);
            default:
                return {};
        }
    }
    if (role == MinimumRole) {
        return column == LengthColumn ? 1 : axis.min;
    }
    if (role == MaximumRole) {
        return column == LengthColumn ? (axis.rotary ? axis.span() - 1 : qint64(axis.max) - cam.on)
                                      : qint64(axis.max);
    }
    return {};
}

bool CamTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (role != Qt::EditRole || !checkIndex(index, CheckIndexOption::IndexIsValid)) {
        return false;
    }
    bool ok = false;
    const qint64 number = value.toLongLong(&ok);
    if (!ok || number < index.data(MinimumRole).toLongLong() ||
        number > index.data(MaximumRole).toLongLong()) {
        return false;
    }
    Cam cam = m_cams.at(index.row());
    switch (index.column()) {
        case OnColumn:
            cam.on = qint32(number);
            break;
        case OffColumn:
            cam.off = qint32(number);
            break;
        case LengthColumn:
            cam = m_document->axis().withLength(cam, number);
            break;
        default:
            return false;
    }
    m_document->setCam(m_program, m_output, index.row(), cam,
                       SetCamCommand::cellKey(m_program, m_output, index.row(), index.column()));
    return true;
}

Qt::ItemFlags CamTableModel::flags(const QModelIndex& index) const {
    Qt::ItemFlags flags = QAbstractTableModel::flags(index);
    if (index.isValid()) {
        flags |= Qt::ItemIsEditable;
    }
    return flags;
}

QVariant CamTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (role != Qt::DisplayRole) {
        return QAbstractTableModel::headerData(section, orientation, role);
    }
    if (orientation == Qt::Vertical) {
        return section + 1;
    }
    switch (section) {
        case OnColumn:
            return tr("On");
        case OffColumn:
            return tr("Off");
        case LengthColumn:
            return tr("Length");
        default:
            return {};
    }
}

}  // namespace cambench
