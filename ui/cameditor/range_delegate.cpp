#include "ui/cameditor/range_delegate.h"

#include "ui/cameditor/editor_roles.h"

#include <QDoubleSpinBox>
#include <QSpinBox>

#include <cmath>

namespace cambench {

RangeDelegate::RangeDelegate(QObject* parent) : QStyledItemDelegate(parent) {}

QWidget* RangeDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                                     const QModelIndex& index) const {
    if (!index.data(MinimumRole).isValid()) {
        return QStyledItemDelegate::createEditor(parent, option, index);
    }
    const int decimals = index.data(DecimalsRole).toInt();
    const QString suffix = index.data(SuffixRole).toString();
    if (decimals > 0) {
        auto* editor = new QDoubleSpinBox(parent);
        editor->setDecimals(decimals);
        editor->setSingleStep(1.0 / std::pow(10.0, decimals));
        editor->setRange(index.data(MinimumRole).toDouble(), index.data(MaximumRole).toDouble());
        editor->setSuffix(suffix);
        editor->setFrame(false);
        return editor;
    }
    auto* editor = new QSpinBox(parent);
    editor->setRange(index.data(MinimumRole).toInt(), index.data(MaximumRole).toInt());
    editor->setSuffix(suffix);
    editor->setFrame(false);
    return editor;
}

void RangeDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const {
    const QVariant value = index.data(Qt::EditRole);
    if (auto* spin = qobject_cast<QSpinBox*>(editor)) {
        spin->setValue(value.toInt());
    } else if (auto* spin = qobject_cast<QDoubleSpinBox*>(editor)) {
        spin->setValue(value.toDouble());
    } else {
        QStyledItemDelegate::setEditorData(editor, index);
    }
}

void RangeDelegate::setModelData(QWidget* editor, QAbstractItemModel* model,
                                 const QModelIndex& index) const {
    if (auto* spin = qobject_cast<QSpinBox*>(editor)) {
        spin->interpretText();
        model->setData(index, spin->value(), Qt::EditRole);
    } else if (auto* spin = qobject_cast<QDoubleSpinBox*>(editor)) {
        spin->interpretText();
        model->setData(index, spin->value(), Qt::EditRole);
    } else {
        QStyledItemDelegate::setModelData(editor, model, index);
    }
}

void RangeDelegate::updateEditorGeometry(QWidget* editor, const QStyleOptionViewItem& option,
                                         const QModelIndex&) const {
    editor->setGeometry(option.rect);
}

}  // namespace cambench
