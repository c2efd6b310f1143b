#pragma once

#include <QFrame>
#include <QLabel>

class QPushButton;

namespace cambench {

class DeviceSession;
class Workspace;

// The connection as the user sees it, in two places: a strip above the
// pages (always there, so nothing jumps when the line is lost) and a dot in
// the status bar. Both say "no answer since HH:MM:SS" as soon as a poll
// cycle went unanswered, and "lost" when the line is gone.
class ConnectionStrip : public QFrame {
    Q_OBJECT
public:
    ConnectionStrip(DeviceSession* session, Workspace* workspace, QWidget* parent = nullptr);

    QString text() const;
    bool isAlarm() const { return m_alarm; }

private:
    void update();

    DeviceSession* m_session;
    Workspace* m_workspace;
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

// A message as one sentence: ends with a full stop unless it already ends
// with punctuation (device and line messages come both ways).
QString asSentence(const QString& text);

}  // namespace cambench
