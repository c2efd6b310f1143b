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
#include <utility>

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
    // A STOP was asked: raises the line's STOP generation at once, on the
    // caller's thread, so that no motion request of a job submitted before
    // now leaves from here on (comm/engine/stop_generation.h); such a job
    // ends Cancelled, "stopped before it moved". Call before the STOP's job.
    // `cause` names what asked where it was not the STOP ("SIGINT").
    virtual void raiseStopGeneration(const QString& cause = {}) = 0;

    // Queues `fn` as a User job that can start motion only when the line is
    // free: no User or Urgent job runs or waits (a short poll may run).
    // Otherwise nothing is queued and the refusal names what holds the line:
    // motion never waits in a queue to start by itself later.
    virtual Result<quint64> submitWhenFree(const QString& title, JobFn fn,
                                           std::function<void()> dropped = {}) = 0;

    virtual ConnectionState state() const = 0;

    // Convenience: runs `work` on the worker thread and `done` with its
    // result on `context`'s thread (queued), unless `context` died. A
    // result that can hold an Error (a Result<>) also comes back when a
    // STOP drops the job unrun: Cancelled, droppedByStop().
    template <class T>
    quint64 run(QObject* context, JobPriority priority, const QString& title,
                std::function<T(JobContext&)> work, std::function<void(T)> done,
                const QString& pollKey = {});
    // As run(), through submitWhenFree(): a refusal comes to `done` (queued)
    // as a Usage error, and 0 is returned. T must hold an Error (a Result<>).
    template <class T>
    quint64 runWhenFree(QObject* context, const QString& title, std::function<T(JobContext&)> work,
                        std::function<void(T)> done);

Q_SIGNALS:
    void connectionStateChanged(cambench::comm::ConnectionState state, const QString& message);
    void jobStarted(quint64 id, const QString& title);
    void jobProgress(quint64 id, qint64 done, qint64 total, const QString& text);
    void jobFinished(quint64 id);
    void traffic(const cambench::comm::TrafficEntry& entry);
};

namespace detail {

// Hands `result` to `done` on `guard`'s thread (queued), unless it died.
template <class T>
void answerQueued(const QPointer<QObject>& guard, const std::function<void(T)>& done, T result) {
    if (!guard) return;
    QMetaObject::invokeMethod(
        guard.data(), [done, result = std::move(result)]() { done(result); }, Qt::QueuedConnection);
}

// run()'s job: `work`, its result handed to `done`; and, where T can hold an
// Error, what a STOP that drops the job unrun hands to `done`.
template <class T>
std::pair<JobRunner::JobFn, std::function<void()>> answeringJob(QObject* context,
                                                                std::function<T(JobContext&)> work,
                                                                std::function<void(T)> done) {
    QPointer<QObject> guard(context);
    std::function<void()> dropped;
    if constexpr (std::is_constructible_v<T, Error>)
        dropped = [guard, done] { answerQueued<T>(guard, done, T(droppedByStop())); };
    JobRunner::JobFn fn = [guard, work = std::move(work), done = std::move(done)](JobContext& ctx) {
        answerQueued<T>(guard, done, work(ctx));
    };
    return {std::move(fn), std::move(dropped)};
}

}  // namespace detail

template <class T>
quint64 JobRunner::run(QObject* context, JobPriority priority, const QString& title,
                       std::function<T(JobContext&)> work, std::function<void(T)> done,
                       const QString& pollKey) {
    auto [fn, dropped] = detail::answeringJob<T>(context, std::move(work), std::move(done));
    return submit(priority, title, std::move(fn), pollKey, std::move(dropped));
}

template <class T>
quint64 JobRunner::runWhenFree(QObject* context, const QString& title,
                               std::function<T(JobContext&)> work, std::function<void(T)> done) {
    static_assert(std::is_constructible_v<T, Error>, "a refusal must reach `done`");
    const QPointer<QObject> guard(context);
    auto [fn, dropped] = detail::answeringJob<T>(context, std::move(work), done);
    const Result<quint64> submitted = submitWhenFree(title, std::move(fn), std::move(dropped));
    if (submitted) return *submitted;
    detail::answerQueued<T>(guard, done, T(submitted.error()));
    return 0;
}

// A new CommWorker, its thread running (defined in comm/worker/comm_worker.cpp).
std::unique_ptr<JobRunner> makeCommWorker(QObject* parent = nullptr);

}  // namespace cambench::comm

Q_DECLARE_METATYPE(cambench::comm::TrafficEntry)
Q_DECLARE_METATYPE(cambench::comm::ConnectionState)
