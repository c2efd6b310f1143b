#pragma once

#include "comm/device/job.h"

#include <QList>
#include <QString>

#include <atomic>
#include <deque>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>

namespace cambench::comm {

using JobFn = std::function<void(JobContext&)>;

struct QueuedJob {
    quint64 id = 0;
    JobPriority priority = JobPriority::User;
    QString title;
    JobFn fn;
    QString pollKey;
    // How many line changes (connect, disconnect, device number) had been
    // posted when the job was submitted: it runs only after all of them.
    quint64 lineEpoch = 0;
    std::shared_ptr<std::atomic_bool> cancel = std::make_shared<std::atomic_bool>(false);
    // Called when a STOP drops the job before it ran (dropQueued()), so
    // that whoever waits for it hears that it was not sent.
    std::function<void()> dropped;
    // The STOP generation when it was submitted: none of its motion
    // requests leaves after a later STOP (comm/engine/stop_generation.h).
    quint64 stopGeneration = 0;
};

// The worker's pending jobs, shared by the front (any thread) and the worker
// thread. Urgent jobs come first, then User jobs, then Poll jobs, first in
// first out within a priority; a Poll job takes the place of a queued Poll job with the same
// key. Knows which job runs, so that cancel() can reach it.
class JobQueue {
public:
    struct Pushed {
        quint64 id = 0;
        quint64 replaced = 0;  // the id of the Poll job it replaced, else 0
    };
    Pushed push(JobPriority priority, QString title, JobFn fn, QString pollKey = {},
                std::function<void()> dropped = {}, quint64 stopGeneration = 0);
    // Pushes a User job only when no User or Urgent job runs or waits (a
    // Poll job may run: it is short, and a User job goes before every
    // queued poll); else pushes nothing and returns the title of the job
    // that holds the line. Checked and pushed under one lock.
    struct PushedIfFree {
        std::optional<Pushed> pushed;
        QString busyWith;
    };
    PushedIfFree pushIfFree(QString title, JobFn fn, std::function<void()> dropped,
                            quint64 stopGeneration);

    // A connect, disconnect or device change is posted to the worker: jobs
    // pushed from now on wait until it has been carried out.
    void lineChangePosted();
    // The next job submitted before the `lineChangesDone`-th line change
    // was posted, now the running one; nothing when there is none. (A job
    // whose line change is not done yet waits for its own turn: a call
    // posted for a job cancelled earlier must not run it before the
    // disconnect or connect the caller asked for first.)
    std::optional<QueuedJob> takeNext(
        quint64 lineChangesDone = std::numeric_limits<quint64>::max());
    void finishRunning();
    // The next Urgent job that may run now, taken while another job runs
    // (between two of its requests). It does not become the running job: an
    // urgent job, once it runs, runs to its end.
    std::optional<QueuedJob> takeUrgent(quint64 lineChangesDone);

    enum class Cancelled { Removed, Signalled, Unknown };
    Cancelled cancel(quint64 id);
    // Removes every queued job (their ids are returned) and signals the
    // running one.
    QList<quint64> cancelAll();
    // Removes every queued User and Poll job and returns them (their
    // `dropped` to be called); the running one and urgent ones go on.
    QList<QueuedJob> dropQueued();

    qsizetype size() const;

private:
    Pushed pushLocked(JobPriority priority, QString title, JobFn fn, QString pollKey,
                      std::function<void()> dropped, quint64 stopGeneration);

    mutable std::mutex m_mutex;
    std::deque<QueuedJob> m_queues[3];  // by JobPriority
    quint64 m_nextId = 1;
    quint64 m_lineChanges = 0;
    quint64 m_runningId = 0;
    JobPriority m_runningPriority = JobPriority::Poll;
    QString m_runningTitle;
    std::shared_ptr<std::atomic_bool> m_runningCancel;
};

}  // namespace cambench::comm
