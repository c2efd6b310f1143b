#pragma once

#include <QStyledItemDelegate>

namespace cambench {

// A spin box editor whose range, decimals and unit come from the model
// (EditorRole), as in qtbase's spinboxdelegate example. Cells without a
// MinimumRole get the default editor.
class RangeDelegate : public QStyledItemDelegate {
    Q_OBJECT

public:
    explicit RangeDelegate(QObject* parent = nullptr);

    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                          const QModelIndex& index) const override;
    void setEditorData(QWidget* editor, const QModelIndex& index) const override;
    void setModelData(QWidget* editor, QAbstractItemModel* model,
                      const QModelIndex& index) const override;
    void updateEditorGeometry(QWidget* editor, const QStyleOptionViewItem& option,
                              const QModelIndex& index) const override;
};

}  // namespace cambench
