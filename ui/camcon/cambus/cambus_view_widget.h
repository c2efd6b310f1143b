#pragma once

#include "comm/camcon/cambus/cambus_view.h"

#include <QElapsedTimer>
#include <QWidget>

#include <functional>

class QLabel;
class QHBoxLayout;
class QTimer;

namespace cambench {

// The Cam-BUS as this PC hears it, live: every user in the bus's table as
// a numbered box, the one holding the token highlighted, the master and
// this PC marked, users that stopped answering greyed; above them how many
// rounds the token makes a second and how many initialisation phases went
// by. Reads the monitor the PC's framing backend fills from the worker
// thread; says so when nothing is heard or the line went quiet.
class CamBusView : public QWidget {
    Q_OBJECT
public:
    explicit CamBusView(comm::CamBusMonitorPtr monitor, QWidget* parent = nullptr);

    // The PC's own number, for the "this PC" mark.
    void setOwnNumber(std::function<int()> number) { m_ownNumber = std::move(number); }
    // Reads the monitor now (the timer does it four times a second).
    void refresh();

    QString summaryText() const;
    // The numbers shown, in order, and the one highlighted (-1: none).
    QList<int> shownUsers() const { return m_shown; }
    int highlightedUser() const { return m_highlighted; }

private:
    void showUsers(const comm::CamBusView& view, bool live);

    comm::CamBusMonitorPtr m_monitor;
    std::function<int()> m_ownNumber;
    QLabel* m_summary;
    QWidget* m_users;
    QHBoxLayout* m_usersLayout;
    QTimer* m_timer;
    QList<int> m_shown;
    int m_highlighted = -1;
    // For the rounds a second and for staleness.
    qint64 m_lastTokens = -1;
    qint64 m_lastNowMs = -1;
    QElapsedTimer m_sinceNews;
    double m_roundsPerSecond = 0;
};

}  // namespace cambench
