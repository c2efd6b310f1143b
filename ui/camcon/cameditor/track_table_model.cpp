#include "ui/camcon/cameditor/track_table_model.h"

#include "model/camcon/data_validation.h"
#include "ui/camcon/cameditor/cam_document.h"
#include "ui/camcon/cameditor/editor_colors.h"
#include "ui/camcon/cameditor/editor_roles.h"

#include <QBrush>
#include <QFont>
#include <QLocale>
#include <QStringList>

namespace cambench {

namespace {
constexpr double kMaximumPulseMs = 10000.0;  // a valve that needs 10 s is no valve
}  // namespace

TrackTableModel::TrackTableModel(CamDocument* document, QObject* parent)
    : QAbstractTableModel(parent), m_document(document), m_rows(document->outputCount()) {
    connect(document, &CamDocument::limitsChanged, this, &TrackTableModel::resetRows);
    connect(document, &CamDocument::trackChanged, this, [this](int program, int output) {
        if (program == m_program) {
            outputChanged(output, CamCountColumn, StateColumn);
        }
    });
    connect(document, &CamDocument::programChanged, this, [this](int program) {
        if (program == m_program && m_rows > 0) {
            Q_EMIT dataChanged(index(0, CamCountColumn), index(m_rows - 1, StateColumn));
        }
    });
    connect(document, &CamDocument::deviceStateChanged, this, [this] {
        if (m_rows > 0) {
            Q_EMIT dataChanged(index(0, 0), index(m_rows - 1, COUNT - 1));
        }
    });
    connect(document, &CamDocument::outputNameChanged, this,
            [this](int output) { outputChanged(output, NameColumn, StateColumn); });
    connect(document, &CamDocument::deadTimeChanged, this,
            [this](int output) { outputChanged(output, DeadTimeColumn, StateColumn); });
    connect(document, &CamDocument::minimumPulsesChanged, this, [this] {
        if (m_rows > 0)
            Q_EMIT dataChanged(index(0, MinimumPulseColumn), index(m_rows - 1, MinimumPulseColumn));
    });
}

void TrackTableModel::setProgram(int program) {
    if (program == m_program) {
        return;
    }
    m_program = program;
    if (m_rows > 0) {
        Q_EMIT dataChanged(index(0, 0), index(m_rows - 1, COUNT - 1));
    }
}

void TrackTableModel::resetRows() {
    beginResetModel();
    m_rows = m_document->outputCount();
    endResetModel();
}

void TrackTableModel::outputChanged(int output, Column first, Column last) {
    const int row = rowForOutput(output);
    if (row >= 0 && row < m_rows) {
        Q_EMIT dataChanged(index(row, first), index(row, last));
    }
}

int TrackTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : m_rows;
}

int TrackTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : COUNT;
}

QVariant TrackTableModel::data(const QModelIndex& index, int role) const {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid)) {
        return {};
    }
    const int output = outputForRow(index.row());
    switch (index.column()) {
        case OutputColumn:
            return role == Qt::DisplayRole ? QVariant(output) : QVariant();
        case NameColumn:
            if (role == Qt::DisplayRole || role == Qt::EditRole) {
                return m_document->outputName(output);
            }
            if (role == Qt::FontRole &&
                m_document->outputNameState(output) == ChangeState::Edited) {
                return editedFont();
            }
            return {};
        case DeadTimeColumn:
            return deadTimeData(output, role);
        case MinimumPulseColumn:
            return minimumPulseData(output, role);
        case CamCountColumn:
            return camCountData(output, role);
        case StateColumn:
            return stateData(output, role);
        default:
            return {};
    }
}

QVariant TrackTableModel::deadTimeData(int output, int role) const {
    const qint32 steps = m_document->deadTime(output);
    if (role == Qt::DisplayRole) return tr("%1 ms").arg(QLocale().toString(steps / 10.0, 'f', 1));
    if (role == Qt::FontRole) {
        return m_document->deadTimeState(output) == ChangeState::Edited ? QVariant(editedFont())
                                                                        : QVariant();
    }
    return millisecondsEditData(steps, m_document->deviceInfo().maxDeadTime / 10.0, role);
}

QVariant TrackTableModel::minimumPulseData(int output, int role) const {
    const qint32 steps = m_document->minimumPulses().value(output);
    switch (role) {
        case Qt::DisplayRole:
            return steps > 0 ? tr("%1 ms").arg(QLocale().toString(steps / 10.0, 'f', 1))
                             : QString();
        case Qt::ToolTipRole:
        case Qt::StatusTipRole:
            return tr("The shortest time output %1 must stay on for its actuator to act. The "
                      "timing view warns where a cam is on for less at the speed chosen. Kept "
                      "on this PC and in the project file, not on the device.")
                .arg(output);
        default:
            return millisecondsEditData(steps, kMaximumPulseMs, role);
    }
}

QVariant TrackTableModel::camCountData(int output, int role) const {
    const QList<CamProblem> problems = m_document->problems(m_program, output);
    switch (role) {
        case Qt::DisplayRole:
            return int(m_document->track(m_program, output).cams.size());
        case Qt::TextAlignmentRole:
            return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
        case Qt::BackgroundRole:
            return problems.isEmpty() ? QVariant() : QVariant(QBrush(errorColor()));
        case Qt::ForegroundRole:
            return problems.isEmpty() ? QVariant() : QVariant(QBrush(Qt::white));
        case Qt::ToolTipRole:
        case Qt::StatusTipRole:
            return problems.isEmpty() ? QVariant() : QVariant(problems.constFirst().message);
        default:
            return {};
    }
}

// A row's state is its cams', its name's and its dead time's together: an
// edited dead time on a track whose cams equal the device's is "edited",
// not "unchanged" (each edit is written, so each must show).
QVariant TrackTableModel::stateData(int output, int role) const {
    const ChangeState cams = m_document->trackState(m_program, output);
    const ChangeState name = m_document->outputNameState(output);
    const ChangeState deadTime = m_document->deadTimeState(output);
    const bool edited = cams == ChangeState::Edited || name == ChangeState::Edited ||
                        deadTime == ChangeState::Edited;
    const ChangeState state = edited ? ChangeState::Edited : cams;
    switch (role) {
        case Qt::DisplayRole:
            switch (state) {
                case ChangeState::Unchanged:
                    return tr("unchanged");
                case ChangeState::Edited:
                    return tr("edited");
                case ChangeState::NotRead:
                    return tr("not read");
            }
            return {};
        case Qt::ToolTipRole:
        case Qt::StatusTipRole:
            return stateText(output, cams, name, deadTime);
        case Qt::FontRole:
            return state == ChangeState::Edited ? QVariant(editedFont()) : QVariant();
        default:
            return {};
    }
}

QString TrackTableModel::stateText(int output, ChangeState cams, ChangeState name,
                                   ChangeState deadTime) const {
    QStringList lines;
    if (cams == ChangeState::Edited) {
        lines << tr("The cams of output %1 were changed and are not yet written to the device.")
                     .arg(output);
    }
    if (name == ChangeState::Edited) {
        lines << tr("The name of output %1 was changed and is not yet written to the device.")
                     .arg(output);
    }
    if (deadTime == ChangeState::Edited) {
        lines << tr("The dead time of output %1 was changed and is not yet written to the "
                    "device.")
                     .arg(output);
    }
    if (cams == ChangeState::NotRead) {
        lines << tr("Program %1 was not read from the device: what the device holds is "
                    "unknown. The cams shown exist on this PC.")
                     .arg(m_program);
    }
    if (lines.isEmpty()) {
        const bool settingsRead = name != ChangeState::NotRead && deadTime != ChangeState::NotRead;
        return settingsRead ? tr("Output %1 is the same as on the device.").arg(output)
                            : tr("The cams of output %1 are the same as on the device. Its "
                                 "name and dead time were not read from it.")
                                  .arg(output);
    }
    return lines.join(QLatin1Char(' '));
}

QFont TrackTableModel::editedFont() {
    QFont font;
    font.setBold(true);
    return font;
}

bool TrackTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (role != Qt::EditRole || !checkIndex(index, CheckIndexOption::IndexIsValid)) {
        return false;
    }
    const int output = outputForRow(index.row());
    if (index.column() == NameColumn) {
        const QString name = value.toString();
        if (!nameProblem(name).isEmpty()) {
            return false;
        }
        m_document->setOutputName(output, name);
        return true;
    }
    if (index.column() == DeadTimeColumn) {
        bool ok = false;
        const qint64 steps = qRound64(value.toDouble(&ok) * 10.0);
        if (!ok || steps < 0 || steps > m_document->deviceInfo().maxDeadTime) {
            return false;
        }
        m_document->setDeadTime(output, qint32(steps));
        return true;
    }
    if (index.column() == MinimumPulseColumn) {
        bool ok = false;
        const qint64 steps = qRound64(value.toDouble(&ok) * 10.0);
        if (!ok || steps < 0 || steps > kMaximumPulseMs * 10) return false;
        m_document->setMinimumPulse(output, qint32(steps));
        return true;
    }
    return false;
}

Qt::ItemFlags TrackTableModel::flags(const QModelIndex& index) const {
    Qt::ItemFlags flags = QAbstractTableModel::flags(index);
    if (index.isValid() && (index.column() == NameColumn || index.column() == DeadTimeColumn ||
                            index.column() == MinimumPulseColumn)) {
        flags |= Qt::ItemIsEditable;
    }
    return flags;
}

QVariant TrackTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) {
        return QAbstractTableModel::headerData(section, orientation, role);
    }
    switch (section) {
        case OutputColumn:
            return tr("Output");
        case NameColumn:
            return tr("Name");
        case DeadTimeColumn:
            return tr("Dead time");
        case MinimumPulseColumn:
            return tr("Min. pulse");
        case CamCountColumn:
            return tr("Cams");
        case StateColumn:
            return tr("State");
        default:
            return {};
    }
}

}  // namespace cambench
