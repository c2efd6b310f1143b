#pragma once

#include "sentence.h"

#include <QFrame>
#include <QLabel>

#include <functional>

class QPushButton;

namespace cambench {

class DeviceSession;

// The connection as the user sees it, in two places: a strip above the
// pages (always there, so nothing jumps when the line is lost) and a dot in
// the status bar. Both say "no answer since HH:MM:SS" as soon as a poll
// cycle went unanswered, and "lost" when the line is gone.
class ConnectionStrip : public QFrame {
    Q_OBJECT
public:
    explicit ConnectionStrip(DeviceSession* session, QWidget* parent = nullptr);

    // The connected device as its family names it ("CamCon 11.10.1994,
    // device number 0."); empty until it has identified itself.
    void setIdentity(std::function<QString()> identity);
    // Shows the state again (the window calls it when the identity changed).
    void update();

    // The whole text, also where the strip shows it shortened.
    QString text() const { return m_lines.join(QLatin1Char('\n')); }
    bool isAlarm() const { return m_alarm; }

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    // Each line on one line of the strip, shortened with "…" where needed:
    // the strip keeps its height whatever the message.
    void showLines();

    QStringList m_lines;
    DeviceSession* m_session;
    std::function<QString()> m_identity;
    QLabel* m_text;
    QPushButton* m_reconnect;
    bool m_alarm = false;
};

class ConnectionIndicator : public QLabel {
    Q_OBJECT
public:
    explicit ConnectionIndicator(DeviceSession* session, QWidget* parent = nullptr);

    // The words beside the dot, without markup.
    QString stateText() const { return m_stateText; }

private:
    void update();

    DeviceSession* m_session;
    QString m_stateText;
};

}  // namespace cambench
