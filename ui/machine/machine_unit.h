#pragma once

#include "comm/usecases/line_answer.h"
#include "model/machine/machine_file.h"

#include <QDateTime>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QTimer>

namespace cambench {

class DeviceSession;
class FamilyGui;
class MainWindow;
class StopControl;

// One device of a machine in the GUI: what the shell is for a single
// device, once per device - its own connection on its own worker
// (DeviceSession), its own families' data on the PC (edits), and its own
// window of pages, shown inside the machine's window. Nothing of it is
// remembered for the next start (the single device's last connection and
// window layout stay the shell's).
class MachineUnit : public QObject {
    Q_OBJECT
public:
    MachineUnit(MachineDevice device, StopControl* machineStop, QObject* parent = nullptr);
    ~MachineUnit() override;

    const MachineDevice& device() const { return m_device; }
    QString name() const { return m_device.name; }
    DeviceSession* session() const { return m_session; }
    QList<FamilyGui*> families() const { return m_families; }
    MainWindow* window() const;

    // A new window of its pages (the one before is deleted): at the start
    // and after a language switch. Owned by whoever shows it.
    MainWindow* createWindow();
    // Connects as the machine file says and reads what a person looks at
    // first; a device the file describes wrongly is not connected
    // (problem() says why).
    void connectDevice();

    // Connected: the device that belongs here identified itself (the
    // machine file's identity, or the first one seen when the file has
    // none) and its family's pages know it. Moving: that, and its own live
    // status says that it moves. AnotherDevice: a device answers with
    // another identity, or not as one of the family's (red, never green).
    // Gone: the line is lost, or nothing answered a whole watch cycle.
    enum class Lamp { Connected, Connecting, Gone, Offline, AnotherDevice, Moving };
    Lamp lamp() const;
    // The lamp in words: "connected", "connected, moving (...)",
    // "connected, may move: jog + sent at ...", "another device answers:
    // ...", "connection lost: ...", ...
    QString stateText() const;
    QString problem() const { return m_problem; }
    int unwrittenCount() const;
    // When the device last answered the line's check (invalid: not yet).
    QDateTime lastAnswer() const { return m_lastAnswer; }

    // The line is checked once a watch cycle (the live pages' poll
    // interval), whether or not a page of the device polls: a device whose
    // line went, which stopped answering or which another one replaced is
    // said within one cycle. Queries only.
    static constexpr int kWatchMs = 500;
    // One cycle now (the timer's; tests).
    void watchLine();
    // Watch cycles since the unit was made (tests count them).
    int watchCycles() const { return m_watchCycles; }

Q_SIGNALS:
    // The lamp, its text or the unwritten count changed.
    void changed();
    void languageRequested(const QString& language);

private:
    // Whether the device answering is the one that belongs here.
    enum class Check { Unchecked, Checking, Confirmed, Another, Silent };
    void lineChanged();
    void checkLineAnswer();
    void watchAnswered(const Result<usecases::LineAnswer>& answer);
    void setCheck(Check check, const QString& text = {});

    MachineDevice m_device;
    StopControl* m_machineStop;
    DeviceSession* m_session;
    QList<FamilyGui*> m_families;
    QPointer<MainWindow> m_window;
    QString m_problem;
    Check m_check = Check::Unchecked;
    QString m_checkText;   // what Another and Silent say
    QString m_answerLine;  // identify()'s line of the device confirmed
    QDateTime m_lastAnswer;
    QTimer m_watch;
    quint64 m_checkJob = 0;      // the full check running
    quint64 m_watchJob = 0;      // the watch cycle's query not answered yet
    quint64 m_watchTicket = 0;   // which watch query an answer belongs to
    bool m_watchOnLine = false;  // ... and it is on the line (not queued)
    // Cycles it has been on the line unanswered: a device is "gone" after
    // two (an answer slower than one cycle on a busy computer is no silence).
    int m_unansweredTicks = 0;
    int m_recheckTicks = 0;
    int m_watchCycles = 0;
};

}  // namespace cambench
