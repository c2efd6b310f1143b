#pragma once

#include "section_page.h"

#include "model/camcon/device_info.h"

#include <QElapsedTimer>
#include <QTimer>

class QCheckBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace cambench {

class DeviceSession;
class LedStrip;
class TrendChart;
class Workspace;

// Live view of the device: position, speed, active program (changeable),
// error state with reset, output and input LEDs, and a trend. Polls with
// Poll jobs under one key, so slow lines never pile polls up.
class MonitorPage : public SectionPage {
    Q_OBJECT
public:
    MonitorPage(DeviceSession* session, Workspace* workspace, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Monitor"); }

    void setPollInterval(int ms);
    void setPaused(bool paused);
    int trendSamples() const;
    static QString errorText(int errorState);

Q_SIGNALS:
    // Every status that arrived (the cam diagram shows it live).
    void statusUpdated(const cambench::DeviceStatus& status);
    void pollingStopped();

private:
    void poll();
    void showStatus(const DeviceStatus& status);
    void updateRunning();

    DeviceSession* m_session;
    Workspace* m_workspace;
    QTimer m_timer;
    QElapsedTimer m_clock;
    bool m_pollPending = false;
    QElapsedTimer m_pollSince;
    QLabel* m_position;
    QLabel* m_speed;
    QLabel* m_program;
    QSpinBox* m_newProgram;
    QLabel* m_error;
    QPushButton* m_reset;
    LedStrip* m_outputs;
    LedStrip* m_inputs;
    TrendChart* m_trend;
    QCheckBox* m_pause;
    QSpinBox* m_rate;
};

}  // namespace cambench
