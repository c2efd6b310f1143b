#include "comm_worker.h"

#include "job_queue.h"
#include "worker_core.h"
#include "worker_logging.h"

#include <QCoreApplication>

namespace cambench::comm {

namespace {

constexpr int kStopWaitMs = 3000;

}  // namespace

struct CommWorker::Impl {
    std::shared_ptr<JobQueue> queue = std::make_shared<JobQueue>();
    std::shared_ptr<StopGeneration> stops = std::make_shared<StopGeneration>();
    QThread* thread = new QThread;
    WorkerCore* core = new WorkerCore(queue, stops);

    template <class F>
    void post(F&& fn) {
        QMetaObject::invokeMethod(core, std::forward<F>(fn), Qt::QueuedConnection);
    }
};

CommWorker::CommWorker(QObject* parent) : JobRunner(parent), d(std::make_unique<Impl>()) {
    qRegisterMetaType<ConnectionState>();
    qRegisterMetaType<TrafficEntry>();

    d->thread->setObjectName(QStringLiteral("CommWorker"));
    d->core->moveToThread(d->thread);
    connect(d->thread, &QThread::finished, d->core, &QObject::deleteLater);

    // The core emits on the worker thread; the front re-emits on its own.
    connect(
        d->core, &WorkerCore::stateChanged, this,
        [this](ConnectionState state, const QString& message) {
            m_state = state;
            Q_EMIT connectionStateChanged(state, message);
        },
        Qt::QueuedConnection);
    connect(d->core, &WorkerCore::jobStarted, this, &CommWorker::jobStarted, Qt::QueuedConnection);
    connect(d->core, &WorkerCore::jobProgress, this, &CommWorker::jobProgress,
            Qt::QueuedConnection);
    connect(d->core, &WorkerCore::jobFinished, this, &CommWorker::jobFinished,
            Qt::QueuedConnection);
    connect(d->core, &WorkerCore::traffic, this, &CommWorker::traffic, Qt::QueuedConnection);
    d->thread->start();
    WorkerCore* core = d->core;
    d->post([core] { core->installOnThread(); });
}

std::unique_ptr<JobRunner> makeCommWorker(QObject* parent) {
    return std::make_unique<CommWorker>(parent);
}

CommWorker::~CommWorker() {
    d->queue->cancelAll();
    d->thread->quit();
    if (d->thread->wait(kStopWaitMs)) {
        delete d->thread;
        return;
    }
    // A job ignores its cancel flag. Terminating the thread could leave the
    // port or a lock half-done, so the thread is left to finish on its own
    // and cleans up after itself.
    qCWarning(commWorkerLog) << "a job did not stop within" << kStopWaitMs
                             << "ms; leaving its thread to finish on its own";
    QThread* thread = d->thread;
    connect(thread, &QThread::finished, thread, &QObject::deleteLater);
}

void CommWorker::connectTo(const ConnectionSettings& connection,
                           const ProtocolSettingsPtr& protocol) {
    WorkerCore* core = d->core;
    d->queue->lineChangePosted();
    d->post([core, connection, protocol] { core->connectTo(connection, protocol); });
}

void CommWorker::disconnectFromDevice() {
    WorkerCore* core = d->core;
    d->queue->lineChangePosted();
    d->post([core] { core->disconnectFromDevice(); });
}

void CommWorker::setLinkDevice(int device) {
    WorkerCore* core = d->core;
    d->queue->lineChangePosted();
    d->post([core, device] { core->setLinkDevice(device); });
}

quint64 CommWorker::submit(JobPriority priority, const QString& title, JobFn fn,
                           const QString& pollKey, std::function<void()> dropped) {
    const JobQueue::Pushed pushed = d->queue->push(priority, title, std::move(fn), pollKey,
                                                   std::move(dropped), d->stops->current());
    if (pushed.replaced != 0) {
        // The replaced poll never runs; it still finishes, like every job.
        QMetaObject::invokeMethod(
            this, [this, id = pushed.replaced] { Q_EMIT jobFinished(id); }, Qt::QueuedConnection);
        // The poll keeps the old one's place but not its line epoch: its
        // own call comes after the line changes it waits for.
    }
    WorkerCore* core = d->core;
    d->post([core] { core->runNextJob(); });
    return pushed.id;
}

Result<quint64> CommWorker::submitWhenFree(const QString& title, JobFn fn,
                                           std::function<void()> dropped) {
    const JobQueue::PushedIfFree pushed =
        d->queue->pushIfFree(title, std::move(fn), std::move(dropped), d->stops->current());
    if (!pushed.pushed)
        return Error::usage(
            QCoreApplication::translate("cambench::comm",
                                        "“%1” is running on this device: motion is not queued "
                                        "(it would start by itself when that ends); ask again then")
                .arg(pushed.busyWith));
    WorkerCore* core = d->core;
    d->post([core] { core->runNextJob(); });
    return pushed.pushed->id;
}

void CommWorker::raiseStopGeneration(const QString& cause) {
    const quint64 raised = d->stops->raise(cause);
    qCInfo(commWorkerLog) << (cause.isEmpty() ? QStringLiteral("STOP") : cause) << "generation"
                          << raised;
}

void CommWorker::cancel(quint64 id) {
    if (d->queue->cancel(id) == JobQueue::Cancelled::Removed) finishDropped({id});
}

void CommWorker::cancelAll() {
    finishDropped(d->queue->cancelAll());
}

void CommWorker::dropQueued() {
    QList<quint64> ids;
    for (const QueuedJob& job : d->queue->dropQueued()) {
        // Its caller hears first that it was not sent, then it finishes.
        if (job.dropped) job.dropped();
        ids << job.id;
    }
    finishDropped(ids);
}

void CommWorker::finishDropped(const QList<quint64>& ids) {
    // A job that never runs still finishes, like every job.
    for (const quint64 id : ids)
        QMetaObject::invokeMethod(
            this, [this, id] { Q_EMIT jobFinished(id); }, Qt::QueuedConnection);
}

}  // namespace cambench::comm
