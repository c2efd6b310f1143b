#pragma once

#include "comm/device/connection_settings.h"
#include "comm/device/job.h"
#include "comm/device/protocol_settings.h"
#include "comm/traffic/traffic_entry.h"

#include <QMetaObject>
#include <QObject>
#include <QPointer>

#include <functional>
#include <memory>
#include <type_traits>

namespace cambench::comm {

enum class ConnectionState { Disconnected, Connecting, Connected, Lost };

// What the GUI may do with the line: connect, run jobs against the connected
// device, cancel them, and hear how they and the connection go. The one
// implementation is the CommWorker (comm/worker/); the GUI sees only this
// face of it, so that no ui/ file includes a worker, engine or transport
// header (the `layering` test checks that).
class JobRunner : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

    using JobFn = std::function<void(JobContext&)>;

    // Opens the transport for `connection` (closing any open one) and the
    // device connection of `protocol` over it. Emits connectionStateChanged.
    virtual void connectTo(const ConnectionSettings& connection,
                           const ProtocolSettingsPtr& protocol) = 0;
    virtual void disconnectFromDevice() = 0;
    virtual void setLinkDevice(int device) = 0;  // bus address for later jobs

    // Queues `fn`; returns the job id. `pollKey` (Poll jobs only) collapses
    // repeated polls. If the link is not connected the job still runs and
    // its calls fail with a Communication error. `dropped` is called (on
    // the thread that calls dropQueued()) when a STOP drops the job unrun.
    virtual quint64 submit(JobPriority priority, const QString& title, JobFn fn,
                           const QString& pollKey = {}, std::function<void()> dropped = {}) = 0;
    virtual void cancel(quint64 id) = 0;  // running or queued
    virtual void cancelAll() = 0;
    // Drops every queued User and Poll job (a move that waits for the line
    // must not run after a STOP); the running job and Urgent ones go on.
    // Each dropped job ends: its `dropped` is called, then jobFinished.
    virtual void dropQueued() = 0;

    virtual ConnectionState state() const = 0;

    // Convenience: runs `work` on the worker thread and `done` with its
    // result on `context`'s thread (queued), unless `context` died. A
    // result that can hold an Error (a Result<>) also comes back when a
    // STOP drops the job unrun: Cancelled, droppedByStop().
    template <class T>
    quint64 run(QObject* context, JobPriority priority, const QString& title,
                std::function<T(JobContext&)> work, std::function<void(T)> done,
                const QString& pollKey = {});

Q_SIGNALS:
    void connectionStateChanged(cambench::comm::ConnectionState state, const QString& message);
    void jobStarted(quint64 id, const QString& title);
    void jobProgress(quint64 id, qint64 done, qint64 total, const QString& text);
    void jobFinished(quint64 id);
    void traffic(const cambench::comm::TrafficEntry& entry);
};

template <class T>
quint64 JobRunner::run(QObject* context, JobPriority priority, const QString& title,
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

// A new CommWorker, its thread running (defined in comm/worker/comm_worker.cpp).
std::unique_ptr<JobRunner> makeCommWorker(QObject* parent = nullptr);

}  // namespace cambench::comm

Q_DECLARE_METATYPE(cambench::comm::TrafficEntry)
Q_DECLARE_METATYPE(cambench::comm::ConnectionState)
