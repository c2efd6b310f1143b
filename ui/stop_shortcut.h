#pragma once

#include <QKeySequence>
#include <QObject>

namespace cambench {

class StopControl;

// The program-wide STOP key (Escape): from every widget of every window,
// dialog and open menu of the program - also from a table's cell editor
// and a spin box, which take Escape for themselves (a QShortcut never sees
// it there), and while a job runs. It watches the key before any widget
// gets it and leaves it to the widget afterwards: the editor still drops
// its edit, the dialog is still cancelled (its Escape button); an open
// menu is closed, every level of it. Only while the STOP can reach a
// device; otherwise Escape is the widgets' as always.
class StopShortcut : public QObject {
    Q_OBJECT
public:
    StopShortcut(StopControl* stop, QObject* parent);
    ~StopShortcut() override;

    static QKeySequence key() { return QKeySequence(Qt::Key_Escape); }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    StopControl* m_stop;
    // One key press reaches the filter once per widget it travels through
    // (the focus widget, then its parents): it stops once.
    const QEvent* m_lastEvent = nullptr;
    quint64 m_lastTimestamp = 0;
};

}  // namespace cambench
