#pragma once

#include <QKeySequence>
#include <QObject>

class QWidget;

namespace cambench {

class StopControl;

// The window-wide STOP key (Escape) from every widget of `window`: also
// from a table's cell editor and a spin box, which take Escape for
// themselves (a QShortcut never sees it there), and while a job runs. It
// watches the key before any widget gets it and leaves it to the widget
// afterwards (the editor still drops its edit). Only while the STOP can
// reach the device; otherwise Escape is the widgets' as always.
class StopShortcut : public QObject {
    Q_OBJECT
public:
    StopShortcut(StopControl* stop, QWidget* window);
    ~StopShortcut() override;

    static QKeySequence key() { return QKeySequence(Qt::Key_Escape); }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    StopControl* m_stop;
    QWidget* m_window;
    // One key press reaches the filter once per widget it travels through
    // (the focus widget, then its parents): it stops once.
    const QEvent* m_lastEvent = nullptr;
    quint64 m_lastTimestamp = 0;
};

}  // namespace cambench
