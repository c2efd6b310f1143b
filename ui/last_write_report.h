#pragma once

#include <QDateTime>
#include <QObject>
#include <QString>

namespace cambench {

// The last write's report, kept after its dialog and its status line are
// gone: a technician who looked away must still be able to read what the
// last write did (Device → Last write report, and the status bar button).
// One per connection (DeviceSession): a machine's devices each have theirs.
class LastWriteReport : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

    void record(const QString& title, const QString& summary, const QString& details,
                bool complete);
    bool isEmpty() const { return m_title.isEmpty(); }
    QString title() const { return m_title; }
    QString summary() const { return m_summary; }
    QString details() const { return m_details; }
    bool complete() const { return m_complete; }
    QDateTime when() const { return m_when; }

Q_SIGNALS:
    void changed();

private:
    QString m_title;
    QString m_summary;
    QString m_details;
    bool m_complete = true;
    QDateTime m_when;
};

}  // namespace cambench
