#pragma once

#include <QStyledItemDelegate>

namespace cambench {

class Mc1WatchModel;

// The editor of a watched variable's value: filled with the controller's
// value once, when it opens, and never again - a poll that brings a new
// value while someone types leaves what was typed alone (the state
// column beside it shows the controller's value meanwhile). What is
// committed is the text as typed, so that the confirmation names exactly
// that.
class Mc1ValueDelegate : public QStyledItemDelegate {
    Q_OBJECT
public:
    explicit Mc1ValueDelegate(Mc1WatchModel* model, QObject* parent = nullptr);

    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                          const QModelIndex& index) const override;
    void setEditorData(QWidget* editor, const QModelIndex& index) const override;
    void setModelData(QWidget* editor, QAbstractItemModel* model,
                      const QModelIndex& index) const override;
    void destroyEditor(QWidget* editor, const QModelIndex& index) const override;

private:
    Mc1WatchModel* m_model;
};

}  // namespace cambench
