#include "stop_shortcut.h"

#include "stop_control.h"

#include <QApplication>
#include <QKeyEvent>
#include <QTimer>
#include <QWidget>

namespace cambench {

namespace {

// Every open menu, every level: Escape alone closes only the innermost.
void closeMenus() {
    while (QWidget* popup = QApplication::activePopupWidget()) {
        if (!popup->close()) break;
    }
}

}  // namespace

StopShortcut::StopShortcut(StopControl* stop, QObject* parent) : QObject(parent), m_stop(stop) {
    QCoreApplication::instance()->installEventFilter(this);
}

StopShortcut::~StopShortcut() {
    // Gone with the application (its child): nothing left to watch.
    if (QCoreApplication::instance()) QCoreApplication::instance()->removeEventFilter(this);
}

bool StopShortcut::eventFilter(QObject* watched, QEvent* event) {
    // The first event of a key press is ShortcutOverride, sent to the
    // focus widget (of a dialog or an open menu too) before a shortcut or
    // the widget itself sees the key.
    if (event->type() != QEvent::ShortcutOverride) return false;
    const auto* key = static_cast<const QKeyEvent*>(event);
    if (key->key() != Qt::Key_Escape || key->modifiers() != Qt::NoModifier || key->isAutoRepeat())
        return false;
    if (!watched->isWidgetType() || !m_stop->armed()) return false;
    if (event == m_lastEvent && key->timestamp() == m_lastTimestamp) return false;
    m_lastEvent = event;
    m_lastTimestamp = key->timestamp();
    // After the key has been delivered: the next key press may get the
    // same address, and the menus still open (a menu bar's) close.
    QTimer::singleShot(0, this, [this] {
        m_lastEvent = nullptr;
        closeMenus();
    });
    m_stop->stopAll();
    return false;  // the widget keeps its Escape (an editor drops its edit, a dialog cancels)
}

}  // namespace cambench
