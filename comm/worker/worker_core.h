#pragma once

#include "comm_worker.h"
#include "guarded_transport.h"
#include "job_queue.h"

#include "comm/engine/stop_generation.h"

#include <QObject>

#include <memory>

namespace cambench::comm {

// The part of CommWorker that lives on its thread: owns the transport and
// the link and runs the queued jobs one at a time. Its methods run only on
// that thread (CommWorker posts to them); its signals reach the front queued.
class WorkerCore : public QObject {
    Q_OBJECT
public:
    WorkerCore(std::shared_ptr<JobQueue> queue, std::shared_ptr<const StopGeneration> stops);
    ~WorkerCore() override;

    void connectTo(const ConnectionSettings& connection, const ProtocolSettingsPtr& protocol);
    void disconnectFromDevice();
    void setLinkDevice(int device);
    // Called on the worker thread once it runs: urgent jobs then run
    // between two requests of a running job (BetweenRequests).
    void installOnThread();
    // Runs the next queued job, if any.
    void runNextJob();

Q_SIGNALS:
    void stateChanged(cambench::comm::ConnectionState state, const QString& message);
    void jobStarted(quint64 id, const QString& title);
    void jobProgress(quint64 id, qint64 done, qint64 total, const QString& text);
    void jobFinished(quint64 id);
    void traffic(const cambench::comm::TrafficEntry& entry);

private:
    void setState(ConnectionState state, const QString& message);
    void checkLine();
    // Keeps a line that carries other users' traffic (a token bus) answered
    // while no job runs.
    void scheduleLineService();
    void serveLine();
    // Runs `job` with the device, its own cancel flag on the engine.
    void runJob(QueuedJob& job);
    // Between two requests of the running job: the urgent jobs queued.
    void runUrgentJobs();

    std::shared_ptr<JobQueue> m_queue;
    std::shared_ptr<const StopGeneration> m_stops;
    GuardedTransport m_line;
    std::unique_ptr<DeviceConnection> m_device;
    quint64 m_lineChangesDone = 0;  // connect, disconnect and device changes carried out
    ConnectionState m_state = ConnectionState::Disconnected;
    bool m_serviceScheduled = false;
    const std::atomic_bool* m_jobCancel = nullptr;  // the running job's
    JobStopMark* m_jobStop = nullptr;               // the running job's
    bool m_inUrgentJob = false;                     // its requests run no other urgent job
};

}  // namespace cambench::comm
