#pragma once

#include "comm/camcon/ascii/ascii_link.h"

#include <QString>

#include <atomic>
#include <functional>

namespace cambench::comm {

// What a running job may use: the link to the device and a way to report
// progress. Passed to the job's function on the worker thread.
class JobContext {
public:
    JobContext(ProtocolLink& link, const std::atomic_bool& cancel,
               std::function<void(qint64 done, qint64 total, const QString& text)> progress)
        : m_link(link), m_cancel(cancel), m_progress(std::move(progress)) {}

    ProtocolLink& link() { return m_link; }
    bool cancelled() const { return m_cancel.load(); }
    void progress(qint64 done, qint64 total, const QString& text = {}) {
        if (m_progress) m_progress(done, total, text);
    }

private:
    ProtocolLink& m_link;
    const std::atomic_bool& m_cancel;
    std::function<void(qint64, qint64, const QString&)> m_progress;
};

// User actions are served before polling (monitor) jobs.
enum class JobPriority { User = 0, Poll = 1 };

}  // namespace cambench::comm
