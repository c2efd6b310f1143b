#pragma once

#include "cli_options.h"
#include "progress_bar.h"
#include "traffic_log_file.h"

#include "comm/worker/comm_worker.h"

#include <QEventLoop>
#include <QObject>

#include <functional>
#include <memory>
#include <optional>

namespace cambench::cli {

// The connection of one cambench-cli run. The device work happens in
// CommWorker jobs; the main thread only runs an event loop until a job's
// result arrives, so it never waits on the line itself.
class CliSession {
public:
    explicit CliSession(GlobalOptions options);
    ~CliSession();

    const GlobalOptions& options() const { return m_options; }

    // Draw a progress bar for the following jobs (only on a terminal).
    void setShowProgress(bool show) { m_showProgress = show; }

    // A job written for one family's device interface (CamConDevice, ...).
    template <class Device, class T>
    using Work = std::function<Result<T>(Device&, comm::JobContext&)>;

    // Connects on first use, runs `work` as one job and returns its result;
    // a Usage error when the connection reaches another family.
    template <class Device, class T>
    Result<T> run(const QString& title, Work<Device, T> work);

    // Runs `work` as one job without connecting first: for work that opens
    // the port itself (detect).
    template <class T>
    Result<T> runUnconnected(const QString& title,
                             std::function<Result<T>(comm::JobContext&)> work);

    // Where the device is, for messages: "sim", "/dev/ttyUSB0 (device 5)".
    QString where() const;

private:
    Status ensureConnected();
    // After SIGINT or SIGTERM no job is submitted: its Cancelled error.
    static std::optional<Error> interrupted();

    GlobalOptions m_options;
    comm::CommWorker m_worker;
    QObject m_context;  // receives the queued results
    ProgressBar m_progress;
    std::unique_ptr<TrafficLogFile> m_log;
    bool m_showProgress = false;
    std::optional<Status> m_connection;
};

template <class Device, class T>
Result<T> CliSession::run(const QString& title, Work<Device, T> work) {
    const Status connected = ensureConnected();
    if (!connected) return connected.error();
    return runUnconnected<T>(title, [work = std::move(work)](comm::JobContext& job) -> Result<T> {
        Result<Device*> device = job.family<Device>();
        if (!device) return device.error();
        return work(**device, job);
    });
}

template <class T>
Result<T> CliSession::runUnconnected(const QString& title,
                                     std::function<Result<T>(comm::JobContext&)> work) {
    if (const std::optional<Error> stopped = interrupted()) return *stopped;
    QEventLoop loop;
    std::optional<Result<T>> result;
    m_worker.run<Result<T>>(&m_context, comm::JobPriority::User, title, std::move(work),
                            [&](Result<T> value) {
                                result.emplace(std::move(value));
                                loop.quit();
                            });
    loop.exec();
    m_progress.finish();
    return std::move(*result);
}

}  // namespace cambench::cli
