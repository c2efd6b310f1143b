#pragma once

#include "mc1_page.h"

#include <QMap>

class QLabel;
class QPushButton;
class QSpinBox;

namespace cambench {

class Mc1AxisParametersBox;

// Axes: one axis's position, target and state, live while shown; home,
// jog, absolute and relative moves and the speed, every motion after a
// confirmation that names the axis and where it goes. Its STOP button is
// one more way to the shell's STOP (MotionStop: every axis, ahead of what
// waits for the line), whose Escape works from every page; the page's
// result line shows its report.
class Mc1AxesPage : public Mc1Page {
    Q_OBJECT
public:
    explicit Mc1AxesPage(DeviceSession* session, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Axes"); }
    bool poll() override;
    void markStale() override;

    QPushButton* stopButton() const { return m_stop; }
    Mc1AxisParametersBox* parametersBox() const { return m_parameters; }
    // "Axes 1, 2, 3 (found with RDTABLE)".
    QLabel* axesLabel() const { return m_axesFound; }
    QLabel* stateLabel() const { return m_state; }
    int axis() const;
    // Asks (naming the motion), then sends it and shows the axis after.
    void command(comm::Mc1AxisCommand command, qint32 value = 0);

protected:
    void factsChanged() override;

private:
    void showState(const comm::Mc1AxisState& state);
    // "axis 1 is jogging + (now at 12)" while a jog runs, else the state's summary.
    QString headline(const comm::Mc1AxisState& state) const;
    // Asks before a command that changes the axis: a motion names the
    // axis and where it goes, Set speed the axis and the speed.
    bool confirmCommand(comm::Mc1AxisCommand command, const QString& what, qint32 value);
    // Asks the controller which axes it has; the axis box offers those.
    void findAxes();
    // Moves offered only while the controller has axes and the STOP can
    // reach it (called again whenever the STOP's reach changes).
    void offerMotion();

    QSpinBox* m_axis;
    QLabel* m_availability;
    QLabel* m_state;
    QLabel* m_details;
    QSpinBox* m_absolute;
    QSpinBox* m_relative;
    QSpinBox* m_speed;
    QPushButton* m_stop;
    Mc1AxisParametersBox* m_parameters;
    QLabel* m_axesFound;
    QList<QWidget*> m_motion;
    // Axes jogging since a jog this page sent (+1 or -1): their headline
    // says "jogging", not the target of an earlier move.
    QMap<int, int> m_jogging;
};

}  // namespace cambench
