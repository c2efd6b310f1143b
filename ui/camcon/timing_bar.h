#pragma once

#include "model/camcon/cam_timing.h"

#include <QWidget>

#include <optional>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QSlider;

namespace cambench {

class CamEditorWidget;
class Workspace;

// "Timing at speed" above the cam diagram: a speed (typed, from the slider,
// or the device's live speed) at which the diagram draws where every output
// really switches - each edge early by speed × its dead time - with each
// cam's duration and the warnings (model/camcon/cam_timing.h). The dead
// times are those on the page (edits included), the dead-time modes where
// the table interface read them, and the minimum pulses of the track table.
class TimingBar : public QWidget {
    Q_OBJECT
public:
    TimingBar(Workspace* workspace, CamEditorWidget* editor, QWidget* parent = nullptr);

    bool timingShown() const;
    void setTimingShown(bool shown);
    // In the axis's unit (1/min rotary, pos/s linear).
    double speed() const;
    void setSpeed(double speed);
    void setFollowDevice(bool follow);
    // The device's speed in positions per second while it is live (the
    // monitor's ?BSPEED), none when it is not.
    void setLiveSpeed(std::optional<double> positionsPerSecond);

    // What the diagram shows (empty while hidden) and the line beside it.
    const QList<OutputTiming>& timing() const { return m_timing; }
    QString summary() const;
    // The top of the slider: the "100 % speed" setting where the settings
    // are read (provisional: taken in the axis unit), else 1000 1/min or
    // ten axis lengths a second.
    double sliderTop() const;

Q_SIGNALS:
    void timingChanged();

protected:
    void changeEvent(QEvent* event) override;

private:
    void recompute();
    void updateSlider();
    void retranslate();
    Axis axis() const;

    Workspace* m_workspace;
    CamEditorWidget* m_editor;
    QCheckBox* m_show;
    QDoubleSpinBox* m_speed;
    QSlider* m_slider;
    QCheckBox* m_follow;
    QLabel* m_summary;
    std::optional<double> m_liveSpeed;  // positions per second
    bool m_liveLost = false;            // following stopped because the speed went stale
    QList<OutputTiming> m_timing;
};

}  // namespace cambench
