#pragma once

#include <QFrame>
#include <QPointer>

class QDialog;
class QLabel;
class QLayout;
class QPushButton;

namespace cambench {

class StopControl;

// Every dialog of the program - ours, Qt's (a file dialog, a message box,
// an input dialog) and the ones written tomorrow - shows a STOP while a
// device that can move is connected: a modal dialog blocks the STOP of the
// window behind it. Watches every dialog as it is shown (an application
// event filter) and gives it a DialogStop; nothing to do in a dialog.
class DialogStops : public QObject {
    Q_OBJECT
public:
    DialogStops(StopControl* stop, QObject* parent);
    ~DialogStops() override;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    // Gives every dialog open now its STOP (a device became able to move).
    void equipOpenDialogs();

    StopControl* m_stop;
};

// A dialog's STOP: a row above the dialog's own widgets with the STOP
// button (red while it can reach a device) and one line of the last STOP's
// report (the whole report in its tool tip). The row has its own space -
// the top margin of the dialog's layout is made that much larger, also of
// a layout the dialog builds anew - so that nothing of the dialog is
// covered and nothing moves once it is shown; a wizard gets it as a button
// beside Back/Next instead (its pages have no layout of the wizard's).
class DialogStop : public QFrame {
    Q_OBJECT
public:
    // `dialog`'s STOP, made once; nullptr when it has one already.
    static DialogStop* equip(QDialog* dialog, StopControl* stop);
    static DialogStop* of(const QDialog* dialog);

    QPushButton* button() const { return m_button; }
    QString reportText() const;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    DialogStop(QDialog* dialog, StopControl* stop);
    void update();
    void showReport(const QString& line, const QString& whole, bool ok);
    // Makes room at the top of the dialog's layout (again when it has a new one).
    void reserveSpace();
    void place();

    QDialog* m_dialog;
    StopControl* m_stop;
    QPushButton* m_button;
    QLabel* m_report = nullptr;
    QPointer<QLayout> m_reserved;  // the layout whose top margin holds the row
    int m_top = 0;                 // its top margin before
};

}  // namespace cambench
