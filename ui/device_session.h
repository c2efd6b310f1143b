#pragma once

#include "comm/camcon/ascii/ascii_camcon.h"
#include "comm/worker/comm_worker.h"

#include <QObject>
#include <QTimer>

#include <functional>

namespace cambench {

// The GUI's one connection: owns the CommWorker, remembers how to reach the
// device, and re-establishes a lost connection by itself (periodic connectTo
// while Lost) so that a replugged adapter comes back without a click. It
// never touches edited data: the workspace keeps it across reconnects.
class DeviceSession : public QObject {
    Q_OBJECT
public:
    explicit DeviceSession(QObject* parent = nullptr);
    ~DeviceSession() override;

    comm::CommWorker& worker() { return m_worker; }

    void connectTo(const comm::ConnectionSettings& connection, const comm::LinkSettings& link);
    void reconnect();  // with the last settings
    void disconnectFromDevice();
    void setDevice(int device);  // Multiuser destination after a bus scan

    comm::ConnectionState state() const { return m_state; }
    // Lost and trying to get the line back by itself.
    bool isRetrying() const { return m_retry.isActive(); }
    bool isOnline() const { return m_state == comm::ConnectionState::Connected; }
    QString stateText() const;  // translated, for the status bar
    QString lastMessage() const { return m_message; }
    const comm::ConnectionSettings& connection() const { return m_connection; }
    const comm::LinkSettings& link() const { return m_link; }

    void setRetryInterval(int ms) { m_retry.setInterval(ms); }

    template <class T>
    using Work = std::function<Result<T>(comm::CamConClient&, comm::JobContext&)>;

    // Runs `work` with a CamConClient on the worker thread's link; `done`
    // gets the result on `context`'s thread. The GUI never waits.
    template <class T>
    quint64 run(QObject* context, const QString& title, Work<T> work,
                std::function<void(Result<T>)> done,
                comm::JobPriority priority = comm::JobPriority::User,
                const QString& pollKey = {}) {
        return m_worker.run<Result<T>>(
            context, priority, title,
            [work = std::move(work)](comm::JobContext& job) {
                comm::CamConClient client(job.link());
                return work(client, job);
            },
            std::move(done), pollKey);
    }

Q_SIGNALS:
    void stateChanged(cambench::comm::ConnectionState state, const QString& message);
    // Connected after having been Lost: the window re-reads the identity.
    void reconnected();

private:
    void onStateChanged(comm::ConnectionState state, const QString& message);

    comm::CommWorker m_worker;
    comm::ConnectionSettings m_connection;
    comm::LinkSettings m_link;
    comm::ConnectionState m_state = comm::ConnectionState::Disconnected;
    QString m_message;
    QTimer m_retry;
    bool m_wasLost = false;
    bool m_wantConnected = false;
};

}  // namespace cambench
