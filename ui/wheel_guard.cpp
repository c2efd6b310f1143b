#include "wheel_guard.h"

#include <QEvent>
#include <QWidget>

namespace cambench {

namespace {

class WheelGuard : public QObject {
public:
    using QObject::QObject;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override {
        auto* widget = qobject_cast<QWidget*>(watched);
        if (event->type() != QEvent::Wheel || !widget || widget->hasFocus()) return false;
        // Filtered and ignored: QApplication hands the wheel to the parents,
        // so the scroll area around the form scrolls.
        event->ignore();
        return true;
    }
};

WheelGuard* guard() {
    static WheelGuard instance;
    return &instance;
}

}  // namespace

void guardWheel(QWidget* editor) {
    editor->setFocusPolicy(Qt::StrongFocus);
    editor->installEventFilter(guard());
}

}  // namespace cambench
