#pragma once

#include "comm/device/job_runner.h"
#include "comm/transport/transport.h"

#include <QList>
#include <QObject>
#include <QThread>

#include <atomic>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>

namespace cambench::comm {

// The JobRunner of the GUI and the CLI: owns the transport and runs jobs on
// its own QThread. Thread-safe front:
// connectTo(), submit(), cancel() may be called from any thread and return
// at once; results come back as queued calls on the submitter's context
// object (see run()). Nothing on the caller's thread waits on the line.
//
// A job is a function that uses the link synchronously on the worker
// thread. Jobs run one at a time; Urgent jobs (a STOP) first, then User
// jobs, then Poll jobs; a Poll job with the same key as a queued one
// replaces it (no pile-up of polls). An Urgent job submitted while another
// job runs does not wait for its end: it runs before that job's next
// request (comm/engine/between_requests.h), so a backup is paused for a
// STOP, not broken.
class CommWorker : public JobRunner {
    Q_OBJECT
public:
    explicit CommWorker(QObject* parent = nullptr);
    ~CommWorker() override;  // stops the thread with a bounded wait

    void connectTo(const ConnectionSettings& connection,
                   const ProtocolSettingsPtr& protocol) override;
    void disconnectFromDevice() override;
    void setLinkDevice(int device) override;

    quint64 submit(JobPriority priority, const QString& title, JobFn fn,
                   const QString& pollKey = {}, std::function<void()> dropped = {}) override;
    void cancel(quint64 id) override;
    void cancelAll() override;
    void dropQueued() override;
    void raiseStopGeneration(const QString& cause = {}) override;
    Result<quint64> submitWhenFree(const QString& title, JobFn fn,
                                   std::function<void()> dropped = {}) override;

    ConnectionState state() const override { return m_state.load(); }

private:
    void finishDropped(const QList<quint64>& ids);

    struct Impl;
    std::unique_ptr<Impl> d;
    std::atomic<ConnectionState> m_state{ConnectionState::Disconnected};
    friend struct Impl;
};

}  // namespace cambench::comm
