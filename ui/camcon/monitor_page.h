#pragma once

#include "ui/camcon/camcon_section_page.h"

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
// error state with reset, output and input LEDs, and a trend. Polls in
// cycles: one Poll job per cycle, never a second while one is unanswered;
// a cycle that finds the last poll unanswered marks every live value stale
// (see LiveFreshness). Polls only while a page shows live values.
class MonitorPage : public CamConSectionPage {
    Q_OBJECT
public:
    MonitorPage(DeviceSession* session, Workspace* workspace, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Monitor"); }
    // Every connect may reach another device: its trend is not the old one's
    // continued (a device of the same identity on another port included).
    void forgetDevice() override;

    // One poll cycle: what the timer does every interval. Public so tests
    // drive cycles instead of waiting for the clock.
    void pollCycle();
    // False: cycles come only from pollCycle() (tests).
    void setTimerDriven(bool on);
    // A page that shows live values is in front (monitor, cam editor).
    void setLiveWanted(bool wanted);
    bool isPolling() const { return m_timer.isActive(); }
    // The last cycle's poll is on the line and not answered yet.
    bool isPollOnLine() const { return m_pollJob != 0 && m_lineClock.isValid(); }

    void setPollInterval(int ms);
    int pollInterval() const { return m_timer.interval(); }
    // Why the interval differs from the one asked for (empty when it does not).
    QString rateNote() const;
    int trendSamples() const;
    TrendChart* trend() const { return m_trend; }
    QString freshnessText() const;
    QString stateText() const;
    static QString errorText(int errorState);

Q_SIGNALS:
    // Every status that arrived (the cam diagram shows it live).
    void statusUpdated(const cambench::DeviceStatus& status);
    // The live values are not live any more (stale, paused or offline).
    void liveEnded();

private:
    void onPollDone(const Result<DeviceStatus>& status);
    void showStatus(const DeviceStatus& status);
    void showFreshness();
    bool onCamCon() const;
    void updateRunning();
    void adaptInterval(qint64 lineMs);
    void setLiveInterval(int ms);

    DeviceSession* m_session;
    Workspace* m_workspace;
    QTimer m_timer;
    QElapsedTimer m_clock;
    bool m_timerDriven = true;
    bool m_liveWanted = false;
    quint64 m_pollJob = 0;      // the poll in flight, 0 = none
    QElapsedTimer m_lineClock;  // started when the poll job reaches the line
    int m_requestedInterval = 250;
    int m_liveInterval = 250;  // the requested one, or slower where the line needs it
    QLabel* m_freshness;
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
    QLabel* m_rateNote;
    int m_lastErrorState = -1;
};

}  // namespace cambench
