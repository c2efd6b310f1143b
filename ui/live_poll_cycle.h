#pragma once

#include <QObject>
#include <QTimer>

namespace cambench {

class DeviceSession;
class LiveDevicePage;

// The poll cycle of a family's live pages: every interval the shown page
// polls, or - when its last poll is still outstanding - the cycle says
// what that means: on the line a whole cycle without an answer, the values
// are stale ("no answer since ..."); queued behind another job (a backup)
// a whole cycle, they are paused and name that job. A page no longer shown
// is paused. Counted in cycles, not against a clock.
class LivePollCycle : public QObject {
    Q_OBJECT
public:
    LivePollCycle(DeviceSession* session, int intervalMs, QObject* parent = nullptr);

    // The page now shown (nullptr: none of this family's live pages); it is
    // polled at once.
    void setShown(LiveDevicePage* page);
    LiveDevicePage* shown() const { return m_shown; }
    // One cycle now (the timer's; tests).
    void tick();

private:
    DeviceSession* m_session;
    QTimer m_timer;
    LiveDevicePage* m_shown = nullptr;
    QString m_lineJob;  // the title of the job on the line now
};

}  // namespace cambench
