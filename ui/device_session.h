#pragma once

#include "comm/device/connection_settings.h"
#include "comm/device/job_runner.h"
#include "comm/device/protocol_settings.h"
#include "last_write_report.h"
#include "live_freshness.h"

#include <QObject>
#include <QPointer>
#include <QTimer>

#include <functional>
#include <memory>

namespace cambench {

class MotionStop;

// The GUI's one connection: owns the job runner (a CommWorker, seen only as
// comm::JobRunner), remembers how to reach the
// device, and re-establishes a lost connection by itself (periodic connectTo
// while Lost) so that a replugged adapter comes back without a click. It
// never touches edited data: the workspace keeps it across reconnects.
class DeviceSession : public QObject {
    Q_OBJECT
public:
    explicit DeviceSession(QObject* parent = nullptr);
    ~DeviceSession() override;

    comm::JobRunner& worker() { return *m_worker; }
    // The one STOP of everything the device on the line can move.
    MotionStop* motionStop() const { return m_motionStop; }

    // Asked before a connect or disconnect takes the line from a device
    // that can move (`action` says what would happen: "Disconnect"); false
    // keeps the line as it is. The window sets it (the question names what
    // moves and offers STOP); without one the line is given up unasked.
    using LeaveCheck = std::function<bool(const QString& action)>;
    void setLeaveCheck(QObject* owner, LeaveCheck check);
    // The same question for a caller that gives up the line itself (quit).
    bool mayLeaveDevice(const QString& action);

    void connectTo(const comm::ConnectionSettings& connection,
                   const comm::ProtocolSettingsPtr& protocol);
    void reconnect();  // with the last settings
    // False: the question before leaving a device that can move was
    // cancelled, and the line is kept as it is.
    bool disconnectFromDevice();
    void setDevice(int device);  // bus address after a bus scan

    comm::ConnectionState state() const { return m_state; }
    // Lost and trying to get the line back by itself.
    bool isRetrying() const { return m_retry.isActive(); }
    // A connect was asked for and not given up (it may not have reached
    // the worker yet, or be retrying).
    bool wantsConnection() const { return m_wantConnected; }
    bool isOnline() const { return m_state == comm::ConnectionState::Connected; }
    QString stateText() const;  // translated, for the status bar
    QString lastMessage() const { return m_message; }
    const comm::ConnectionSettings& connection() const { return m_connection; }
    // The protocol's settings of the last connect (never null).
    const comm::ProtocolSettings& protocol() const { return *m_protocol; }
    comm::ProtocolSettingsPtr protocolSettings() const { return m_protocol; }

    void setRetryInterval(int ms) { m_retry.setInterval(ms); }

    // Whether the device on the line has been identified since the last
    // connect (checkConnectedDevice): until then nothing is written, and the
    // banner does not name a device.
    bool deviceChecked() const { return m_deviceChecked; }
    void setDeviceChecked(bool checked);
    // Said by the family's check before setDeviceChecked(true): the device
    // that answers is not the one answering before.
    void noteAnotherDevice() { m_anotherDevice = true; }
    // The family's check found no device of its own on the line (`why`):
    // said red until the next connect or a device identifies itself. Empty
    // while nothing failed.
    void setIdentifyFailed(const QString& why);
    QString identifyProblem() const { return m_identifyProblem; }

    // How old the live values are; fed by the monitor's poll cycles, made
    // stale by a lost line, reset by a connect to another device.
    LiveFreshness* freshness() { return &m_freshness; }
    // The last write to a device over this connection, for the window.
    LastWriteReport& lastWriteReport() { return m_lastWrite; }

    // A job written for one family's device interface (CamConDevice, ...).
    template <class Device, class T>
    using Work = std::function<Result<T>(Device&, comm::JobContext&)>;

    // Runs `work` with the connected device on the worker thread; `done`
    // gets the result on `context`'s thread. The GUI never waits. A Usage
    // error when the connection reaches another family.
    template <class Device, class T>
    quint64 run(QObject* context, const QString& title, Work<Device, T> work,
                std::function<void(Result<T>)> done,
                comm::JobPriority priority = comm::JobPriority::User, const QString& pollKey = {}) {
        return m_worker->run<Result<T>>(context, priority, title,
                                        onFamily<Device, T>(std::move(work)), std::move(done),
                                        pollKey);
    }

    // As run(), for a job that can start motion or change a drive's power
    // (a move, a jog, a start, enable, a program run): queued only when the
    // line is free; when another job runs or waits, `done` gets the refusal
    // at once, naming it (comm::JobRunner::submitWhenFree). Motion never
    // waits in a queue to start by itself later.
    template <class Device, class T>
    quint64 runMotion(QObject* context, const QString& title, Work<Device, T> work,
                      std::function<void(Result<T>)> done) {
        return m_worker->runWhenFree<Result<T>>(
            context, title, onFamily<Device, T>(std::move(work)), std::move(done));
    }

Q_SIGNALS:
    void stateChanged(cambench::comm::ConnectionState state, const QString& message);
    // Connected after having been Lost: the window re-reads the identity.
    void reconnected();
    // After reconnected(): the device answered and its identity was checked
    // (`sameDevice`: the one that answered before the line was lost).
    void reestablished(bool sameDevice);
    // Another device number on the same line (Multiuser): another device.
    void targetChanged();
    void deviceCheckedChanged(bool checked);
    // identifyProblem() changed.
    void identifyProblemChanged();

private:
    void onStateChanged(comm::ConnectionState state, const QString& message);
    // `work` with the connected device as `Device`; a Usage error when the
    // connection reaches another family.
    template <class Device, class T>
    static std::function<Result<T>(comm::JobContext&)> onFamily(Work<Device, T> work) {
        return [work = std::move(work)](comm::JobContext& job) -> Result<T> {
            Result<Device*> device = job.family<Device>();
            if (!device) return device.error();
            return work(**device, job);
        };
    }

    std::unique_ptr<comm::JobRunner> m_worker;
    MotionStop* m_motionStop = nullptr;
    QPointer<QObject> m_leaveOwner;
    LeaveCheck m_leaveCheck;
    comm::ConnectionSettings m_connection;
    comm::ProtocolSettingsPtr m_protocol;
    comm::ConnectionState m_state = comm::ConnectionState::Disconnected;
    QString m_message;
    QTimer m_retry;
    LiveFreshness m_freshness;
    LastWriteReport m_lastWrite;
    bool m_wasLost = false;
    bool m_reestablishing = false;  // reconnected, the device not checked yet
    bool m_anotherDevice = false;
    bool m_wantConnected = false;
    bool m_deviceChecked = false;
    QString m_identifyProblem;
};

}  // namespace cambench
