#include "job_queue.h"

#include <algorithm>

namespace cambench::comm {

JobQueue::Pushed JobQueue::push(JobPriority priority, QString title, JobFn fn, QString pollKey,
                                std::function<void()> dropped, quint64 stopGeneration) {
    std::lock_guard lock(m_mutex);
    return pushLocked(priority, std::move(title), std::move(fn), std::move(pollKey),
                      std::move(dropped), stopGeneration);
}

JobQueue::PushedIfFree JobQueue::pushIfFree(QString title, JobFn fn, std::function<void()> dropped,
                                            quint64 stopGeneration) {
    std::lock_guard lock(m_mutex);
    if (m_runningId != 0 && m_runningPriority != JobPriority::Poll) return {{}, m_runningTitle};
    for (const JobPriority priority : {JobPriority::Urgent, JobPriority::User})
        if (!m_queues[int(priority)].empty()) return {{}, m_queues[int(priority)].front().title};
    return {pushLocked(JobPriority::User, std::move(title), std::move(fn), {}, std::move(dropped),
                       stopGeneration),
            {}};
}

JobQueue::Pushed JobQueue::pushLocked(JobPriority priority, QString title, JobFn fn,
                                      QString pollKey, std::function<void()> dropped,
                                      quint64 stopGeneration) {
    QueuedJob job;
    job.id = m_nextId++;
    job.priority = priority;
    job.title = std::move(title);
    job.fn = std::move(fn);
    job.pollKey = priority == JobPriority::Poll ? std::move(pollKey) : QString();
    job.lineEpoch = m_lineChanges;
    job.dropped = std::move(dropped);
    job.stopGeneration = stopGeneration;

    auto& queue = m_queues[int(priority)];
    if (!job.pollKey.isEmpty()) {
        const auto same = std::find_if(queue.begin(), queue.end(), [&](const QueuedJob& queued) {
            return queued.pollKey == job.pollKey;
        });
        if (same != queue.end()) {
            const quint64 replaced = same->id;
            *same = std::move(job);
            return {same->id, replaced};
        }
    }
    queue.push_back(std::move(job));
    return {queue.back().id, 0};
}

void JobQueue::lineChangePosted() {
    std::lock_guard lock(m_mutex);
    ++m_lineChanges;
}

std::optional<QueuedJob> JobQueue::takeNext(quint64 lineChangesDone) {
    std::lock_guard lock(m_mutex);
    for (auto& queue : m_queues) {
        if (queue.empty() || queue.front().lineEpoch > lineChangesDone) continue;
        QueuedJob job = std::move(queue.front());
        queue.pop_front();
        m_runningId = job.id;
        m_runningPriority = job.priority;
        m_runningTitle = job.title;
        m_runningCancel = job.cancel;
        return job;
    }
    return std::nullopt;
}

std::optional<QueuedJob> JobQueue::takeUrgent(quint64 lineChangesDone) {
    std::lock_guard lock(m_mutex);
    auto& urgent = m_queues[int(JobPriority::Urgent)];
    if (urgent.empty() || urgent.front().lineEpoch > lineChangesDone) return std::nullopt;
    QueuedJob job = std::move(urgent.front());
    urgent.pop_front();
    return job;
}

void JobQueue::finishRunning() {
    std::lock_guard lock(m_mutex);
    m_runningId = 0;
    m_runningTitle.clear();
    m_runningCancel.reset();
}

JobQueue::Cancelled JobQueue::cancel(quint64 id) {
    std::lock_guard lock(m_mutex);
    if (id != 0 && id == m_runningId) {
        m_runningCancel->store(true);
        return Cancelled::Signalled;
    }
    for (auto& queue : m_queues) {
        const auto it = std::find_if(queue.begin(), queue.end(),
                                     [id](const QueuedJob& job) { return job.id == id; });
        if (it != queue.end()) {
            queue.erase(it);
            return Cancelled::Removed;
        }
    }
    return Cancelled::Unknown;
}

QList<quint64> JobQueue::cancelAll() {
    std::lock_guard lock(m_mutex);
    QList<quint64> removed;
    for (auto& queue : m_queues) {
        for (const QueuedJob& job : queue) removed.append(job.id);
        queue.clear();
    }
    if (m_runningCancel) m_runningCancel->store(true);
    return removed;
}

QList<QueuedJob> JobQueue::dropQueued() {
    std::lock_guard lock(m_mutex);
    QList<QueuedJob> removed;
    for (const JobPriority priority : {JobPriority::User, JobPriority::Poll}) {
        auto& queue = m_queues[int(priority)];
        for (QueuedJob& job : queue) removed.append(std::move(job));
        queue.clear();
    }
    return removed;
}

qsizetype JobQueue::size() const {
    std::lock_guard lock(m_mutex);
    qsizetype queued = 0;
    for (const auto& queue : m_queues) queued += qsizetype(queue.size());
    return queued;
}

}  // namespace cambench::comm
