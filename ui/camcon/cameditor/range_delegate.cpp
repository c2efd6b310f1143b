#include "ui/camcon/cameditor/range_delegate.h"

#include "ui/camcon/cameditor/editor_roles.h"

#include <QDoubleSpinBox>
#include <QKeyEvent>
#include <QLocale>
#include <QSpinBox>
#include <QToolTip>

#include <cmath>
#include <limits>

namespace cambench {

namespace {
// Far beyond any cell's range: the editor must not cut what is typed.
constexpr double kTypingLimit = 1e9;
const char* const kMinimum = "cambenchMinimum";
const char* const kMaximum = "cambenchMaximum";

double editorValue(QWidget* editor) {
    if (auto* spin = qobject_cast<QSpinBox*>(editor)) {
        spin->interpretText();
        return spin->value();
    }
    if (auto* spin = qobject_cast<QDoubleSpinBox*>(editor)) {
        spin->interpretText();
        return spin->value();
    }
    return 0;
}
}  // namespace

RangeDelegate::RangeDelegate(QObject* parent) : QStyledItemDelegate(parent) {}

QWidget* RangeDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                                     const QModelIndex& index) const {
    if (!index.data(MinimumRole).isValid()) {
        return QStyledItemDelegate::createEditor(parent, option, index);
    }
    const int decimals = index.data(DecimalsRole).toInt();
    const QString suffix = index.data(SuffixRole).toString();
    const double minimum = index.data(MinimumRole).toDouble();
    const double maximum = index.data(MaximumRole).toDouble();
    QAbstractSpinBox* editor = nullptr;
    if (decimals > 0) {
        auto* spin = new QDoubleSpinBox(parent);
        spin->setDecimals(decimals);
        spin->setSingleStep(1.0 / std::pow(10.0, decimals));
        spin->setRange(std::min(minimum, 0.0), kTypingLimit);
        spin->setSuffix(suffix);
        editor = spin;
    } else {
        auto* spin = new QSpinBox(parent);
        spin->setRange(std::min(int(minimum), 0), std::numeric_limits<int>::max());
        spin->setSuffix(suffix);
        editor = spin;
    }
    editor->setFrame(false);
    editor->setProperty(kMinimum, minimum);
    editor->setProperty(kMaximum, maximum);
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

QString RangeDelegate::refusal(QWidget* editor) const {
    if (!editor->property(kMaximum).isValid()) return {};
    const double value = editorValue(editor);
    const double minimum = editor->property(kMinimum).toDouble();
    const double maximum = editor->property(kMaximum).toDouble();
    if (value >= minimum && value <= maximum) return {};
    const int decimals = qobject_cast<QDoubleSpinBox*>(editor)
                             ? qobject_cast<QDoubleSpinBox*>(editor)->decimals()
                             : 0;
    const QString suffix = qobject_cast<QAbstractSpinBox*>(editor)->property("suffix").toString();
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);  // as typed
    return tr("%1%2 is not taken: this device allows %3 … %4%2.")
        .arg(locale.toString(value, 'f', decimals), suffix, locale.toString(minimum, 'f', decimals),
             locale.toString(maximum, 'f', decimals));
}

void RangeDelegate::refuse(QWidget* editor, const QString& reason) const {
    m_lastRefusal = reason;
    QToolTip::showText(editor->mapToGlobal(QPoint(0, editor->height())), reason, editor);
    Q_EMIT valueRefused(reason);
}

bool RangeDelegate::eventFilter(QObject* object, QEvent* event) {
    auto* editor = qobject_cast<QWidget*>(object);
    if (editor && event->type() == QEvent::KeyPress) {
        const int key = static_cast<QKeyEvent*>(event)->key();
        if (key == Qt::Key_Return || key == Qt::Key_Enter) {
            const QString reason = refusal(editor);
            if (!reason.isEmpty()) {
                // The editor stays open with what was typed, and says why.
                refuse(editor, reason);
                return true;
            }
        }
    }
    return QStyledItemDelegate::eventFilter(object, event);
}

void RangeDelegate::setModelData(QWidget* editor, QAbstractItemModel* model,
                                 const QModelIndex& index) const {
    if (!qobject_cast<QSpinBox*>(editor) && !qobject_cast<QDoubleSpinBox*>(editor)) {
        QStyledItemDelegate::setModelData(editor, model, index);
        return;
    }
    if (const QString reason = refusal(editor); !reason.isEmpty()) {
        refuse(editor, reason + QLatin1Char(' ') + tr("The cell keeps its value."));
        return;
    }
    m_lastRefusal.clear();
    model->setData(index, editorValue(editor), Qt::EditRole);
}

void RangeDelegate::updateEditorGeometry(QWidget* editor, const QStyleOptionViewItem& option,
                                         const QModelIndex&) const {
    editor->setGeometry(option.rect);
}

}  // namespace cambench
