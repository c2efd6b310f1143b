#pragma once

#include "compax3_page.h"

#include <optional>

class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace cambench {

// Motion: enable/disable, jog + and −, move set n with target, velocity,
// acceleration and deceleration; each asks first, saying what will move or
// that power drops. The set's values and mode are read from the drive when
// a set is chosen; a start writes only what the person changed, the
// question names each value and when it was read, and the start reads the
// set again first: when the drive holds other values, nothing is sent and
// the question comes again with them.
// Its STOP button is one more way to the shell's STOP (MotionStop), whose
// Escape works from every page; the page's result line shows its report.
class Compax3MotionPage : public Compax3Page {
    Q_OBJECT
public:
    explicit Compax3MotionPage(DeviceSession* session, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Motion"); }
    bool poll() override;

    void runMotion(comm::Compax3Motion motion);
    // Reads the chosen set from the drive into the editors.
    void readSet();
    void moveSet();
    QPushButton* stopButton() const { return m_stop; }
    QString axisText() const;

protected:
    void factsChanged() override;
    void freshnessChanged() override;

private:
    // Enables the motions while the drive is known and the STOP reaches it.
    void offerMotion();
    void finished(const QString& what, const Result<comm::Compax3CommandResult>& result);
    void showSet(const comm::Compax3SetValues& values);
    // The drive held other values than the confirmation showed: what was
    // not typed follows the drive, and the start is asked again.
    void setChanged(const comm::Compax3SetValues& now, const QString& note);
    bool confirmDisable();

    QLabel* m_axis;
    QSpinBox* m_set;
    QDoubleSpinBox* m_target;
    QDoubleSpinBox* m_velocity;
    QDoubleSpinBox* m_acceleration;
    QDoubleSpinBox* m_deceleration;
    QLabel* m_mode;
    // Said at the top of the next start question (why it is asked again).
    QString m_askAgain;
    // The set as last read from the drive: what a start compares against.
    std::optional<comm::Compax3SetValues> m_read;
    QPushButton* m_stop;
    QList<QPushButton*> m_actions;
    bool m_stale = false;
    std::optional<comm::Compax3DriveStatus> m_shown;  // the axis as last read
};

}  // namespace cambench
