#pragma once

#include "model/result.h"
#include "stop_control.h"

#include <QPointer>

namespace cambench {

class DeviceSession;

// The one STOP of the GUI (issue 27): the shell's button and shortcut and
// the motion pages' own STOP buttons all call stopAll() here, whatever page
// is shown and whatever job runs. Whether the device on the line can move
// anything is asked once per connection and identity (the device's
// MotionControl, nullptr for a CamCon) and kept here. A device of a machine
// hands its STOP to the machine's (joinMachine), which stops every device.
class MotionStop : public StopControl {
    Q_OBJECT
public:
    explicit MotionStop(DeviceSession* session);

    // The device on the line (or, while the line is lost, the last one) can
    // move something: a STOP is shown.
    bool available() const override { return m_available; }
    // A STOP can reach the device now: shown and online.
    bool armed() const override;

    // Stops everything the device can move, without a question: drops what
    // waits for the line (a queued move must not follow the STOP) and runs
    // ahead of everything, between two requests of a running job.
    // stopFinished() reports per axis or drive. In a machine: the
    // machine's STOP, every device's.
    void stopAll() override;
    // The STOP of this device alone (what stopAll() does outside a machine).
    void stopThisDevice();
    // What a STOP does first, at once: no motion request of a job asked
    // before now leaves (comm::JobRunner::raiseStopGeneration).
    void raiseStopGeneration();
    bool stopRunning() const { return m_stopRunning; }
    // From now on every STOP of this device is `machine`'s (nullptr: its own).
    void joinMachine(StopControl* machine) { m_machine = machine; }

    // What moves or is powered, asked from the device; an error when it
    // cannot tell, also when no answer came within `timeoutMs` (the GUI
    // waits that long in a local event loop).
    Result<QStringList> activeMotion(int timeoutMs);
    // stopAll() and its report, waiting at most `timeoutMs`; an error when
    // no report came in that time.
    Result<comm::MotionStopReport> stopAndWait(int timeoutMs);

    // What is known of the device's motion, for the machine's list. A fact
    // only from the device's own live status read by a page that polls it;
    // a move the device acknowledged, a STOP not acknowledged everywhere or
    // a status no longer polled only make it "may move". Forgotten with
    // the line or another device.
    enum class Motion { Unknown, Standing, Moving, MayMove };
    Motion motion() const { return m_motion; }
    // "moving (axis 1 is jogging +)", "may move (jog + sent at 12:03:04)",
    // "STOP acknowledged at 12:03:05"; empty when nothing is known.
    QString motionText() const { return m_motionText; }
    // A page read the device's status now: Moving or Standing is a fact;
    // Unknown says the status read tells nothing of the whole device (one
    // axis of several stands) and forgets a "moving" said before.
    // `page`: the page that read it.
    void noteLiveStatus(const QObject* page, Motion motion, const QString& what);
    // `page` no longer polls it (not shown, no answer): what it read last
    // is no fact any more (another page's is).
    void noteLiveStatusOld(const QObject* page);
    // The device acknowledged a move, jog or start (`what`).
    void noteMotionSent(const QString& what);

    // The report for a person: one line per axis or drive, "acknowledged"
    // or "NOT acknowledged - use the machine's emergency stop".
    static QString reportText(const comm::MotionStopReport& report);
    static QString reportSummary(const comm::MotionStopReport& report);
    // The titles of its jobs: the status bar leaves them out (the STOP
    // reports in its bar, and must not hide the backup it interrupts).
    static QStringList jobTitles();

Q_SIGNALS:
    void motionChanged();

private:
    void setMotion(Motion motion, const QString& text);
    // Asks the worker whether the device on the line has a MotionControl.
    void askAvailability();
    void setAvailable(bool available);

    DeviceSession* m_session;
    bool m_available = false;
    bool m_stopRunning = false;
    quint64 m_asked = 0;  // the last availability question; older answers are dropped
    QPointer<StopControl> m_machine;
    Motion m_motion = Motion::Unknown;
    QString m_motionText;
    QPointer<const QObject> m_liveFrom;  // the page whose status m_motion is
    QTime m_liveAt;
};

}  // namespace cambench
