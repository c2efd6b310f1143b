#include "worker_core.h"

#include <QCoreApplication>
#include <QTimer>

#include <utility>

#include "worker_logging.h"

#include "comm/device/protocol_registry.h"
#include "comm/engine/between_requests.h"
#include "comm/transport/transport_registry.h"

namespace cambench::comm {

namespace {
// How long one look at a bus line takes between jobs: a job waits at most this.
constexpr int kServeSliceMs = 20;
}  // namespace

WorkerCore::WorkerCore(std::shared_ptr<JobQueue> queue, std::shared_ptr<const StopGeneration> stops)
    : m_queue(std::move(queue)), m_stops(std::move(stops)) {}

void WorkerCore::installOnThread() {
    // Every request of a job runs on this thread: urgent jobs run between them.
    BetweenRequests::install([this] { runUrgentJobs(); });
}

WorkerCore::~WorkerCore() = default;

void WorkerCore::setState(ConnectionState state, const QString& message) {
    m_state = state;
    Q_EMIT stateChanged(state, message);
}

void WorkerCore::connectTo(const ConnectionSettings& connection,
                           const ProtocolSettingsPtr& protocol) {
    ++m_lineChangesDone;
    m_device.reset();
    m_line.detach(QCoreApplication::translate("cambench::comm", "not connected: connecting to %1")
                      .arg(connection.port));
    setState(ConnectionState::Connecting, connection.port);
    const ProtocolInfo* info =
        protocol ? ProtocolRegistry::instance().find(protocol->protocolId()) : nullptr;
    Status opened = success();
    if (!info) {
        opened = Error::usage(
            QCoreApplication::translate("cambench::comm", "unknown protocol \"%1\"; known: %2")
                .arg(protocol ? protocol->protocolId() : QString(),
                     ProtocolRegistry::instance().idList()));
    }
    ConnectionSettings line = connection;
    if (info) {
        line.protocol = info->id;
        line.serial.inBandBreaks = info->defaultSerial.inBandBreaks;
    }
    Result<std::unique_ptr<Transport>> transport =
        opened ? makeTransport(line) : Result<std::unique_ptr<Transport>>(opened.error());
    if (opened) opened = transport ? (*transport)->open() : Status(transport.error());
    if (!opened) {
        qCWarning(commWorkerLog) << "cannot connect:" << opened.error().message;
        m_line.detach(QCoreApplication::translate("cambench::comm", "not connected: %1")
                          .arg(opened.error().message));
        setState(ConnectionState::Disconnected, opened.error().message);
        return;
    }
    const QString description = (*transport)->description();
    m_line.attach(std::move(transport.value()));
    Result<std::unique_ptr<DeviceConnection>> device =
        info->connect(m_line, *protocol, lineTimingFor(connection.serial));
    if (!device) {
        m_line.detach(QCoreApplication::translate("cambench::comm", "not connected: %1")
                          .arg(device.error().message));
        setState(ConnectionState::Disconnected, device.error().message);
        return;
    }
    m_device = std::move(device).value();
    m_device->engine().setTrafficSink([this](const TrafficEntry& entry) { Q_EMIT traffic(entry); });
    m_device->engine().setStopGeneration(m_stops.get());
    qCInfo(commWorkerLog) << "connected to" << description;
    setState(ConnectionState::Connected, description);
    scheduleLineService();
}

void WorkerCore::scheduleLineService() {
    if (m_serviceScheduled || !m_device || !m_device->engine().backend().carriesOtherTraffic())
        return;
    m_serviceScheduled = true;
    QTimer::singleShot(0, this, &WorkerCore::serveLine);
}

void WorkerCore::serveLine() {
    m_serviceScheduled = false;
    if (!m_device || !m_line.isOpen() || !m_device->engine().backend().carriesOtherTraffic())
        return;
    // A bus user answers the line between jobs too (Cam-BUS: its DIDs),
    // or the bus waits on it and takes it for gone. Queued jobs run between
    // these slices.
    const Status served = m_device->engine().listen(kServeSliceMs);
    if (!served) qCDebug(commWorkerLog) << "serving the line:" << served.error().message;
    checkLine();
    scheduleLineService();
}

void WorkerCore::disconnectFromDevice() {
    ++m_lineChangesDone;
    m_line.detach(
        QCoreApplication::translate("cambench::comm", "not connected to a device; connect first"));
    if (m_state != ConnectionState::Disconnected)
        setState(ConnectionState::Disconnected, QString());
}

void WorkerCore::setLinkDevice(int device) {
    ++m_lineChangesDone;
    if (m_device) m_device->setDevice(device);
}

void WorkerCore::checkLine() {
    if (!m_line.lineLost()) return;
    const QString message = m_line.lossMessage();
    qCWarning(commWorkerLog) << "line lost:" << message;
    m_line.detach(QCoreApplication::translate("cambench::comm", "not connected: %1").arg(message));
    setState(ConnectionState::Lost, message);
}

void WorkerCore::runNextJob() {
    std::optional<QueuedJob> job = m_queue->takeNext(m_lineChangesDone);
    if (!job) return;
    runJob(*job);
    m_queue->finishRunning();
    checkLine();
    scheduleLineService();
}

void WorkerCore::runUrgentJobs() {
    if (m_inUrgentJob) return;
    while (std::optional<QueuedJob> job = m_queue->takeUrgent(m_lineChangesDone)) {
        qCDebug(commWorkerLog) << "urgent job between two requests of the running job";
        m_inUrgentJob = true;
        runJob(*job);
        m_inUrgentJob = false;
    }
}

void WorkerCore::runJob(QueuedJob& job) {
    const quint64 id = job.id;
    qCDebug(commWorkerLog) << "job" << id << "started:" << job.title;
    Q_EMIT jobStarted(id, job.title);
    // An urgent job inside another has its own cancel flag: cancelling the
    // interrupted backup must not cancel the STOP; the backup's comes back
    // after it.
    const std::atomic_bool* interrupted = std::exchange(m_jobCancel, job.cancel.get());
    // Its own STOP mark, too: a STOP inside a move it interrupts is not stopped by it.
    JobStopMark mark{job.stopGeneration, std::nullopt};
    JobStopMark* interruptedMark = std::exchange(m_jobStop, &mark);
    if (m_device) {
        m_device->engine().setCancelFlag(m_jobCancel);
        m_device->engine().setJobStopMark(m_jobStop);
    }
    JobContext context(m_device.get(), m_line.reason(), *job.cancel,
                       [this, id](qint64 done, qint64 total, const QString& text) {
                           Q_EMIT jobProgress(id, done, total, text);
                       });
    job.fn(context);
    m_jobCancel = interrupted;
    m_jobStop = interruptedMark;
    if (m_device) {
        m_device->engine().setCancelFlag(m_jobCancel);
        m_device->engine().setJobStopMark(m_jobStop);
    }
    qCDebug(commWorkerLog) << "job" << id << "finished";
    Q_EMIT jobFinished(id);
}

}  // namespace cambench::comm
