#pragma once

#include "compax3_page.h"

class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace cambench {

// Motion: enable/disable, jog + and −, move set n with target, velocity and
// acceleration; each asks first, saying that the axis will move. Its STOP
// button is one more way to the shell's STOP (MotionStop), whose Escape
// works from every page; the page's result line shows its report.
class Compax3MotionPage : public Compax3Page {
    Q_OBJECT
public:
    explicit Compax3MotionPage(DeviceSession* session, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Motion"); }
    bool poll() override;
    void markStale() override;

    void runMotion(comm::Compax3Motion motion);
    void moveSet();
    // The shell's STOP.
    void stop();
    QPushButton* stopButton() const { return m_stop; }
    QString axisText() const;

protected:
    void factsChanged() override;

private:
    void finished(const QString& what, const Result<comm::Compax3DriveStatus>& status);

    QLabel* m_axis;
    QSpinBox* m_set;
    QDoubleSpinBox* m_target;
    QDoubleSpinBox* m_velocity;
    QDoubleSpinBox* m_acceleration;
    QPushButton* m_stop;
    QList<QPushButton*> m_actions;
    bool m_stale = false;
};

}  // namespace cambench
