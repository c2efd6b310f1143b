#pragma once

#include "comm/device/protocol_settings.h"
#include "comm/traffic/traffic_entry.h"
#include "comm/transport/transport.h"
#include "job.h"

#include <QList>
#include <QObject>
#include <QPointer>
#include <QThread>

#include <atomic>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <type_traits>

namespace cambench::comm {

enum class ConnectionState { Disconnected, Connecting, Connected, Lost };

// Owns the transport and runs jobs on its own QThread. Thread-safe front:
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
class CommWorker : public QObject {
    Q_OBJECT
public:
    explicit CommWorker(QObject* parent = nullptr);
    ~CommWorker() override;  // stops the thread with a bounded wait

    using JobFn = std::function<void(JobContext&)>;

    // Opens the transport for `connection` (closing any open one) and the
    // device connection of `protocol` over it. Emits connectionStateChanged.
    void connectTo(const ConnectionSettings& connection, const ProtocolSettingsPtr& protocol);
    void disconnectFromDevice();
    void setLinkDevice(int device);  // bus address for later jobs

    // Queues `fn`; returns the job id. `pollKey` (Poll jobs only) collapses
    // repeated polls. If the link is not connected the job still runs and
    // its calls fail with a Communication error. `dropped` is called (on
    // the thread that calls dropQueued()) when a STOP drops the job unrun.
    quint64 submit(JobPriority priority, const QString& title, JobFn fn,
                   const QString& pollKey = {}, std::function<void()> dropped = {});
    void cancel(quint64 id);  // running or queued
    void cancelAll();
    // Drops every queued User and Poll job (a move that waits for the line
    // must not run after a STOP); the running job and Urgent ones go on.
    // Each dropped job ends: its `dropped` is called, then jobFinished.
    void dropQueued();

    // Convenience: runs `work` on the worker thread and `done` with its
    // result on `context`'s thread (queued), unless `context` died. A
    // result that can hold an Error (a Result<>) also comes back when a
    // STOP drops the job unrun: Cancelled, droppedByStop().
    template <class T>
    quint64 run(QObject* context, JobPriority priority, const QString& title,
                std::function<T(JobContext&)> work, std::function<void(T)> done,
                const QString& pollKey = {});

    ConnectionState state() const { return m_state.load(); }

Q_SIGNALS:
    void connectionStateChanged(cambench::comm::ConnectionState state, const QString& message);
    void jobStarted(quint64 id, const QString& title);
    void jobProgress(quint64 id, qint64 done, qint64 total, const QString& text);
    void jobFinished(quint64 id);
    void traffic(const cambench::comm::TrafficEntry& entry);

private:
    void finishDropped(const QList<quint64>& ids);

    struct Impl;
    std::unique_ptr<Impl> d;
    std::atomic<ConnectionState> m_state{ConnectionState::Disconnected};
    friend struct Impl;
};

template <class T>
quint64 CommWorker::run(QObject* context, JobPriority priority, const QString& title,
                        std::function<T(JobContext&)> work, std::function<void(T)> done,
                        const QString& pollKey) {
    QPointer<QObject> guard(context);
    std::function<void()> dropped;
    if constexpr (std::is_constructible_v<T, Error>) {
        dropped = [guard, done] {
            if (!guard) return;
            QMetaObject::invokeMethod(
                guard.data(), [done]() { done(T(droppedByStop())); }, Qt::QueuedConnection);
        };
    }
    return submit(
        priority, title,
        [guard, work = std::move(work), done = std::move(done)](JobContext& ctx) {
            T result = work(ctx);
            if (!guard) return;
            QMetaObject::invokeMethod(
                guard.data(), [done, result = std::move(result)]() { done(result); },
                Qt::QueuedConnection);
        },
        pollKey, std::move(dropped));
}

}  // namespace cambench::comm

Q_DECLARE_METATYPE(cambench::comm::TrafficEntry)
Q_DECLARE_METATYPE(cambench::comm::ConnectionState)
