#pragma once

#include "job.h"

#include <QList>
#include <QString>

#include <atomic>
#include <deque>
#include <functional>
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
    std::shared_ptr<std::atomic_bool> cancel = std::make_shared<std::atomic_bool>(false);
};

// The worker's pending jobs, shared by the front (any thread) and the worker
// thread. User jobs come before Poll jobs, first in first out within a
// priority; a Poll job takes the place of a queued Poll job with the same
// key. Knows which job runs, so that cancel() can reach it.
class JobQueue {
public:
    struct Pushed {
        quint64 id = 0;
        quint64 replaced = 0;  // the id of the Poll job it replaced, else 0
    };
    Pushed push(JobPriority priority, QString title, JobFn fn, QString pollKey = {});

    // The next job, now the running one; nothing when the queue is empty.
    std::optional<QueuedJob> takeNext();
    void finishRunning();

    enum class Cancelled { Removed, Signalled, Unknown };
    Cancelled cancel(quint64 id);
    // Removes every queued job (their ids are returned) and signals the
    // running one.
    QList<quint64> cancelAll();

    qsizetype size() const;

private:
    mutable std::mutex m_mutex;
    std::deque<QueuedJob> m_queues[2];  // by JobPriority
    quint64 m_nextId = 1;
    quint64 m_runningId = 0;
    std::shared_ptr<std::atomic_bool> m_runningCancel;
};

}  // namespace cambench::comm
