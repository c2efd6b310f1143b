#include "worker_core.h"

#include "worker_logging.h"

#include "comm/transport/transport_factory.h"

namespace cambench::comm {

WorkerCore::WorkerCore(std::shared_ptr<JobQueue> queue) : m_queue(std::move(queue)) {
    makeLink(LinkSettings{});
}

WorkerCore::~WorkerCore() = default;

void WorkerCore::makeLink(const LinkSettings& settings) {
    m_link = std::make_unique<ProtocolLink>(m_line, settings);
    m_link->setTrafficSink([this](const TrafficEntry& entry) { Q_EMIT traffic(entry); });
}

void WorkerCore::setState(ConnectionState state, const QString& message) {
    m_state = state;
    Q_EMIT stateChanged(state, message);
}

void WorkerCore::connectTo(const ConnectionSettings& connection, const LinkSettings& link) {
    m_line.detach(QStringLiteral("not connected: connecting to %1").arg(connection.port));
    setState(ConnectionState::Connecting, connection.port);
    Result<std::unique_ptr<Transport>> transport = makeTransport(connection);
    Status opened = transport ? (*transport)->open() : Status(transport.error());
    if (!opened) {
        qCWarning(commWorkerLog) << "cannot connect:" << opened.error().message;
        m_line.detach(QStringLiteral("not connected: %1").arg(opened.error().message));
        setState(ConnectionState::Disconnected, opened.error().message);
        return;
    }
    const QString description = (*transport)->description();
    m_line.attach(std::move(transport.value()));
    makeLink(link);
    qCInfo(commWorkerLog) << "connected to" << description;
    setState(ConnectionState::Connected, description);
}

void WorkerCore::disconnectFromDevice() {
    m_line.detach(QStringLiteral("not connected to a device; connect first"));
    if (m_state != ConnectionState::Disconnected)
        setState(ConnectionState::Disconnected, QString());
}

void WorkerCore::setLinkDevice(int device) {
    m_link->setDevice(device);
}

void WorkerCore::checkLine() {
    if (!m_line.lineLost()) return;
    const QString message = m_line.lossMessage();
    qCWarning(commWorkerLog) << "line lost:" << message;
    m_line.detach(QStringLiteral("not connected: %1").arg(message));
    setState(ConnectionState::Lost, message);
}

void WorkerCore::runNextJob() {
    std::optional<QueuedJob> job = m_queue->takeNext();
    if (!job) return;
    const quint64 id = job->id;
    qCDebug(commWorkerLog) << "job" << id << "started:" << job->title;
    Q_EMIT jobStarted(id, job->title);
    m_link->setCancelFlag(job->cancel.get());
    JobContext context(*m_link, *job->cancel,
                       [this, id](qint64 done, qint64 total, const QString& text) {
                           Q_EMIT jobProgress(id, done, total, text);
                       });
    job->fn(context);
    m_link->setCancelFlag(nullptr);
    m_queue->finishRunning();
    qCDebug(commWorkerLog) << "job" << id << "finished";
    Q_EMIT jobFinished(id);
    checkLine();
}

}  // namespace cambench::comm
