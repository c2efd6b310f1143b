#pragma once

#include "device_session.h"
#include "section_page.h"

#include <functional>

class QLabel;
class QPushButton;

namespace cambench {

class LiveFreshness;

// A page that shows a device's live values and acts on the device (the
// MC-1's and the Compax3's pages): polled while shown, marked stale when
// the line goes, asks before it acts, and says under itself what the last
// action did.
//
// Its values have their own freshness (a page not shown is not polled, so
// its values are older than the line's): a poll run with runPoll() is
// judged by the poll cycle (LivePollCycle) - a cycle it spends on the line
// without an answer makes the values stale, a cycle it spends queued
// behind another job (a backup) pauses them. Values added with
// addLiveValue() are greyed and say so whenever they are not live.
class LiveDevicePage : public SectionPage {
    Q_OBJECT
public:
    explicit LiveDevicePage(DeviceSession* session, QWidget* parent = nullptr);

    DeviceSession* session() const { return m_session; }
    // One poll of the live values the page shows; false: it has none.
    virtual bool poll() { return false; }
    // The line went away or another device came: shown values go stale.
    virtual void markStale() {}
    // Another device came (or another family's): what the last action did
    // was done to the device before, and is no longer said.
    void clearResult();
    // The result line goes and the values shown are no longer live.
    void forgetDevice() override;

    // The page whose poll fills this one (a trend drawn from another
    // page's values); the poll cycle polls and judges that one.
    virtual LiveDevicePage* polledPage() { return this; }
    // How old the values shown on this page are.
    LiveFreshness* freshness() const { return m_freshness; }
    enum class PollState { Idle, Queued, OnLine };
    // Where the page's last runPoll() is: answered, waiting, or on the line.
    PollState pollState() const;
    // The poll cycle's verdicts: a whole cycle on the line with no answer
    // and none arriving (stale), a whole cycle queued behind `reason`
    // (paused), or not polled because the page is not shown (paused).
    void pollMissed();
    void pollPaused(const QString& reason);
    void pollStopped();
    // The line is gone: the values are stale now, whatever the cycle says.
    void lineLost();
    // What the page's STOP does: the shell's STOP (MotionStop::stopAll).
    void stopAll();

protected:
    // A poll of the page's values at Poll priority under `pollKey`, one at
    // a time (none is queued while one is outstanding); `shown` gets what
    // was read, a failure makes the values stale (a cancel does not).
    // With `notRead`, a refusal is an answer (the line is alive, the values
    // were not read) and a read refused before it was sent (Usage) says
    // nothing of the line; `notRead` gets either.
    template <class Device, class T>
    void runPoll(const QString& title, DeviceSession::Work<Device, T> work,
                 std::function<void(const T&)> shown, const QString& pollKey,
                 std::function<void(const Error&)> notRead = {}) {
        if (m_pollJob != 0) return;
        m_pollOnLine = false;
        m_pollProgress = false;
        m_pollJob = m_session->run<Device, T>(
            this, title, std::move(work),
            [this, shown = std::move(shown), notRead = std::move(notRead)](Result<T> result) {
                m_pollJob = 0;
                if (!result && result.error().kind == ErrorKind::Cancelled) return;
                if (result || !notRead) {
                    pollAnswered(result.ok());
                    if (result) shown(*result);
                    return;
                }
                const ErrorKind kind = result.error().kind;
                // A request this device or protocol lacks, or a wrong
                // argument, says nothing about the line.
                if (kind != ErrorKind::Usage && kind != ErrorKind::Unsupported)
                    pollAnswered(kind == ErrorKind::DeviceError);
                notRead(result.error());
            },
            comm::JobPriority::Poll, pollKey);
    }
    // The device's own status as this page read it now, for the machine's
    // list (MotionStop::noteLiveStatus): said as a fact only while this
    // page's values are live.
    void reportMotion(bool moving, bool wholeDevice, const QString& what);
    // The device acknowledged a move, jog or start: it may move now.
    void reportMotionSent(const QString& what);
    // A warning box: `question` with `detail` below, Cancel the default; a
    // button named `title` confirms. True on that button.
    bool confirm(const QString& title, const QString& question, const QString& detail = {});
    // A live-value poll came back: tells the page's and the session's freshness.
    void pollAnswered(bool ok);
    // A widget showing a live value: greyed, with the freshness as its
    // tool tip, whenever the page's values are not live.
    void addLiveValue(QWidget* widget);
    // "Live, last answer 12:03:04" / "No answer since 12:03:04" / "Paused
    // (Back up controller); values of 12:03:04" ("pageFreshness").
    QLabel* freshnessLine();
    // The page's freshness changed (after the live values were re-styled):
    // for values addLiveValue() cannot grey (table models, LED strips).
    virtual void freshnessChanged() {}
    // The line under the page that says what the last action did
    // ("pageResult").
    QLabel* resultLine();
    void showResult(const QString& text, bool ok);
    // The page's own STOP ("STOP (Esc)", named `objectName`, `toolTip`
    // says what it stops) as one more way to the shell's STOP: the result
    // line shows every STOP's report and the values are read again;
    // `armedChanged` when the STOP can reach the device or no longer can
    // (a page offers its moves only while it can). The page places it.
    QPushButton* makeShellStop(const QString& objectName, const QString& toolTip,
                               std::function<void()> armedChanged);

private:
    void showFreshness();

    DeviceSession* m_session;
    LiveFreshness* m_freshness;
    QList<QWidget*> m_liveValues;
    QLabel* m_freshnessLine = nullptr;
    QLabel* m_result = nullptr;
    quint64 m_pollJob = 0;
    bool m_pollOnLine = false;
    bool m_pollProgress = false;   // answers arrived for the poll since the last cycle
    bool m_reportsMotion = false;  // reportMotion() was called: its status goes old with it
};

}  // namespace cambench
