#pragma once

#include <QFrame>

class QLabel;
class QPushButton;

namespace cambench {

class StopControl;

// The shell's STOP, above every page while the device on the line (or, in
// a machine, a device of the machine) can move something: a big button,
// red while it can reach the device and grey (never looking armed) while it
// cannot, and the last STOP's report beside it, one line per axis or drive.
class StopBar : public QFrame {
    Q_OBJECT
public:
    StopBar(StopControl* stop, const QString& shortcutText, QWidget* parent = nullptr);

    QPushButton* button() const { return m_button; }
    QString reportText() const;

private:
    void update();
    void showReport();

    StopControl* m_stop;
    QPushButton* m_button;
    QLabel* m_report;
};

}  // namespace cambench
