#include "mc1_value_delegate.h"

#include "mc1_watch_model.h"

#include <QLineEdit>
#include <QRegularExpressionValidator>

namespace cambench {

namespace {
// Set on an editor once it holds the controller's value (or typed text).
constexpr char kFilled[] = "cambenchFilled";
}  // namespace

Mc1ValueDelegate::Mc1ValueDelegate(Mc1WatchModel* model, QObject* parent)
    : QStyledItemDelegate(parent), m_model(model) {}

QWidget* Mc1ValueDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem&,
                                        const QModelIndex& index) const {
    auto* editor = new QLineEdit(parent);
    editor->setObjectName(QStringLiteral("mc1ValueEditor"));
    editor->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    // A whole number with a sign: the controller's variables are integers.
    editor->setValidator(new QRegularExpressionValidator(
        QRegularExpression(QStringLiteral("\\s*[-+]?\\d{0,11}\\s*")), editor));
    m_model->setEditingRow(index.row());
    return editor;
}

void Mc1ValueDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const {
    // Qt calls this again when the cell's value changes (a poll): what is
    // in the editor then is the person's, not the controller's.
    if (editor->property(kFilled).toBool()) return;
    auto* line = static_cast<QLineEdit*>(editor);
    const QVariant value = index.data(Qt::DisplayRole);
    const QString text = value.toString();
    line->setText(text == QStringLiteral("—") ? QString() : text);
    line->selectAll();
    editor->setProperty(kFilled, true);
}

void Mc1ValueDelegate::setModelData(QWidget* editor, QAbstractItemModel* model,
                                    const QModelIndex& index) const {
    model->setData(index, static_cast<QLineEdit*>(editor)->text(), Qt::EditRole);
}

void Mc1ValueDelegate::destroyEditor(QWidget* editor, const QModelIndex& index) const {
    m_model->setEditingRow(-1);
    QStyledItemDelegate::destroyEditor(editor, index);
}

}  // namespace cambench
