#pragma once

#include <QStyledItemDelegate>

namespace cambench {

// A spin box editor whose range, decimals and unit come from the model
// (EditorRole), as in qtbase's spinboxdelegate example. Cells without a
// MinimumRole get the default editor.
//
// The editor takes any number of digits: a spin box limited to the range
// would silently drop the last digit of "1500" (leaving 150.0) when 999.9
// is the maximum. A value outside the range is refused with a word instead:
// Enter keeps the editor open and says why; leaving the cell keeps the old
// value and says so.
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

    // Why the last value was refused (empty: the last one was taken).
    QString lastRefusal() const { return m_lastRefusal; }

Q_SIGNALS:
    void valueRefused(const QString& reason) const;

protected:
    bool eventFilter(QObject* object, QEvent* event) override;

private:
    // Empty when the editor's value is inside the cell's range.
    QString refusal(QWidget* editor) const;
    void refuse(QWidget* editor, const QString& reason) const;

    mutable QString m_lastRefusal;
};

}  // namespace cambench
