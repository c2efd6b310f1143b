#include "stop_shortcut.h"

#include "stop_control.h"

#include <QApplication>
#include <QKeyEvent>
#include <QTimer>
#include <QWidget>

namespace cambench {

StopShortcut::StopShortcut(StopControl* stop, QWidget* window)
    : QObject(window), m_stop(stop), m_window(window) {
    qApp->installEventFilter(this);
}

StopShortcut::~StopShortcut() {
    qApp->removeEventFilter(this);
}

bool StopShortcut::eventFilter(QObject* watched, QEvent* event) {
    // The first event of a key press is ShortcutOverride, sent to the
    // focus widget before a shortcut or the widget itself sees the key.
    if (event->type() != QEvent::ShortcutOverride) return false;
    const auto* key = static_cast<const QKeyEvent*>(event);
    if (key->key() != Qt::Key_Escape || key->modifiers() != Qt::NoModifier || key->isAutoRepeat())
        return false;
    const auto* widget = qobject_cast<const QWidget*>(watched);
    if (!widget || widget->window() != m_window || !m_stop->armed()) return false;
    if (event == m_lastEvent && key->timestamp() == m_lastTimestamp) return false;
    m_lastEvent = event;
    m_lastTimestamp = key->timestamp();
    // The next key press may get the same address: forgotten once this
    // one has been delivered.
    QTimer::singleShot(0, this, [this] { m_lastEvent = nullptr; });
    m_stop->stopAll();
    return false;  // the widget keeps its Escape (an editor drops its edit)
}

}  // namespace cambench
