#pragma once

#include "comm/device/progress.h"

#include <QString>

#include <functional>

namespace cambench::comm {
class JobContext;
}

namespace cambench::usecases {

// How a use case reports how far it is and learns that the user cancelled.
// Made from a worker job's JobContext (GUI and CLI) or from plain functions
// (tests). A default-constructed one reports nothing and is never
// cancelled. Cheap to copy; a slice maps a part of the work onto a range of
// the whole, so that one bar covers several steps.
class UseCaseProgress {
public:
    using ReportFn = std::function<void(qint64 done, qint64 total, const QString& text)>;
    using CancelledFn = std::function<bool()>;

    UseCaseProgress() = default;
    explicit UseCaseProgress(ReportFn report, CancelledFn cancelled = {});
    // Reports through job.progress() and asks job.cancelled(). The job must
    // outlive every copy.
    static UseCaseProgress of(comm::JobContext& job);

    void report(qint64 done, qint64 total, const QString& text = {}) const;
    bool cancelled() const;

    // For device calls that take a comm::ProgressFn: reports with `text`.
    comm::ProgressFn forDevice(const QString& text) const;

    // A part of the work that fills steps [first, first + count) of
    // `total`: the part reports its own done/total, scaled into that range.
    UseCaseProgress slice(qint64 first, qint64 count, qint64 total) const;

private:
    ReportFn m_report;
    CancelledFn m_cancelled;
};

}  // namespace cambench::usecases
