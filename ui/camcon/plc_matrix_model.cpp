#include "plc_matrix_model.h"

#include "plc_symbol.h"
#include "ui/change_marker.h"
#include "workspace.h"

namespace cambench {

PlcMatrixModel::PlcMatrixModel(Workspace* workspace, QObject* parent)
    : QAbstractTableModel(parent), m_workspace(workspace) {
    connect(workspace, &Workspace::plcChanged, this, &PlcMatrixModel::refresh);
}

void PlcMatrixModel::setNetwork(int area, int number) {
    m_area = area;
    m_number = number;
    refresh();
}

void PlcMatrixModel::refresh() {
    Q_EMIT dataChanged(index(0, 0), index(PlcNetwork::kPaths - 1, PlcNetwork::kSymbolsPerPath - 1));
}

int PlcMatrixModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : PlcNetwork::kPaths;
}

int PlcMatrixModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : PlcNetwork::kSymbolsPerPath;
}

QVariant PlcMatrixModel::data(const QModelIndex& index, int role) const {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid)) return {};
    const int slot = index.row() * PlcNetwork::kSymbolsPerPath + index.column();
    const quint16 word = m_workspace->plcNetwork(m_area, m_number).symbols[slot];
    const int key = Workspace::plcKey(m_area, m_number);
    const std::optional<PlcNetwork> device = m_workspace->plc().deviceValue(key);
    const bool changed =
        device ? device->symbols[slot] != word : m_workspace->plc().value(key).has_value();
    switch (role) {
        case Qt::DisplayRole:
            return (changed ? changedMarker() : QString()) + plcsymbol::display(word);
        case Qt::EditRole:
            return plcsymbol::editText(word);
        case Qt::FontRole:
            return changed ? QVariant(changedFont()) : QVariant();
        case Qt::TextAlignmentRole:
            return Qt::AlignCenter;
        case Qt::ToolTipRole:
            return tr("Path %1, symbol %2: word %3 (provisional decoding: high byte operand kind, "
                      "low byte number; enter 4 hex digits or e.g. M11)")
                .arg(index.row() + 1)
                .arg(index.column() + 1)
                .arg(plcsymbol::editText(word));
        default:
            return {};
    }
}

bool PlcMatrixModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (role != Qt::EditRole || !checkIndex(index, CheckIndexOption::IndexIsValid)) return false;
    const auto word = plcsymbol::parse(value.toString());
    if (!word) {
        Q_EMIT entryRefused(plcsymbol::whyNot(value.toString()));
        return false;
    }
    PlcNetwork network = m_workspace->plcNetwork(m_area, m_number);
    network.symbols[index.row() * PlcNetwork::kSymbolsPerPath + index.column()] = *word;
    m_workspace->plc().edit(Workspace::plcKey(m_area, m_number), network);
    return true;
}

Qt::ItemFlags PlcMatrixModel::flags(const QModelIndex& index) const {
    return QAbstractTableModel::flags(index) |
           (index.isValid() ? Qt::ItemIsEditable : Qt::NoItemFlags);
}

QVariant PlcMatrixModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (role != Qt::DisplayRole) return {};
    return orientation == Qt::Horizontal ? tr("Symbol %1").arg(section + 1)
                                         : tr("Path %1").arg(section + 1);
}

}  // namespace cambench
