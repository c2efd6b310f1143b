#include "use_case_progress.h"

#include "comm/device/job.h"

namespace cambench::usecases {

UseCaseProgress::UseCaseProgress(ReportFn report, CancelledFn cancelled)
    : m_report(std::move(report)), m_cancelled(std::move(cancelled)) {}

UseCaseProgress UseCaseProgress::of(comm::JobContext& job) {
    return UseCaseProgress(
        [&job](qint64 done, qint64 total, const QString& text) { job.progress(done, total, text); },
        [&job] { return job.cancelled(); });
}

void UseCaseProgress::report(qint64 done, qint64 total, const QString& text) const {
    if (m_report) m_report(done, total, text);
}

bool UseCaseProgress::cancelled() const {
    return m_cancelled && m_cancelled();
}

comm::ProgressFn UseCaseProgress::forDevice(const QString& text) const {
    const UseCaseProgress self = *this;
    return [self, text](qint64 done, qint64 total) { self.report(done, total, text); };
}

UseCaseProgress UseCaseProgress::slice(qint64 first, qint64 count, qint64 total) const {
    const UseCaseProgress outer = *this;
    return UseCaseProgress(
        [outer, first, count, total](qint64 done, qint64 partTotal, const QString& text) {
            // The part's fraction of its own total, placed into its range.
            const qint64 within =
                partTotal > 0 ? qBound<qint64>(0, done, partTotal) * count / partTotal : 0;
            outer.report(first + within, total, text);
        },
        m_cancelled);
}

}  // namespace cambench::usecases
