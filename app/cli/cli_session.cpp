#include "cli_session.h"

#include "interrupt_watch.h"

#include <QTimer>

#include <csignal>

namespace cambench::cli {

namespace {

// Opening a serial port or a TCP connection is bounded by the transport;
// this only guards against a worker that never reports back.
constexpr int kConnectGuardMs = 60000;

}  // namespace

CliSession::CliSession(GlobalOptions options) : m_options(std::move(options)) {
    InterruptWatch::add(&m_worker);
    QObject::connect(&m_worker, &comm::CommWorker::jobProgress, &m_context,
                     [this](quint64, qint64 done, qint64 total, const QString& text) {
                         if (m_showProgress) m_progress.update(done, total, text);
                     });
    if (!m_options.logFile.isEmpty()) {
        m_log = std::make_unique<TrafficLogFile>(m_options.logFile);
        QObject::connect(&m_worker, &comm::CommWorker::traffic, &m_context,
                         [this](const comm::TrafficEntry& entry) { m_log->append(entry); });
    }
}

CliSession::~CliSession() {
    InterruptWatch::remove(&m_worker);
    m_worker.disconnectFromDevice();
}

std::optional<Error> CliSession::interrupted() {
    const int signal = InterruptWatch::received();
    if (signal == 0) return std::nullopt;
    return Error{ErrorKind::Cancelled,
                 QStringLiteral("not sent: cambench-cli was interrupted (%1)")
                     .arg(signal == SIGINT ? QStringLiteral("SIGINT") : QStringLiteral("SIGTERM")),
                 0};
}

QString CliSession::where() const {
    if (m_options.isBus()) {
        return QStringLiteral("%1 (device %2)")
            .arg(m_options.port)
            .arg(m_options.protocolSettings()->device());
    }
    return m_options.port;
}

Status CliSession::ensureConnected() {
    if (m_connection) return *m_connection;

    QEventLoop loop;
    bool finished = false;
    Status outcome = Error::communication(
        QStringLiteral("no answer from the connection to %1; check the port name").arg(where()));
    QObject::connect(&m_worker, &comm::CommWorker::connectionStateChanged, &loop,
                     [&](comm::ConnectionState state, const QString& message) {
                         if (state == comm::ConnectionState::Connected) {
                             outcome = success();
                             finished = true;
                             loop.quit();
                         } else if (state != comm::ConnectionState::Connecting) {
                             outcome = Error::communication(
                                 message.isEmpty()
                                     ? QStringLiteral("cannot open %1; check the port name and "
                                                      "that no other program uses it")
                                           .arg(where())
                                     : message);
                             finished = true;
                             loop.quit();
                         }
                     });
    QTimer::singleShot(kConnectGuardMs, &loop, &QEventLoop::quit);
    m_worker.connectTo(m_options.connection(), m_options.protocolSettings());
    if (!finished) loop.exec();  // the worker may have reported synchronously
    m_connection = outcome;
    if (m_log && outcome.ok()) m_log->note(QStringLiteral("connected to %1").arg(where()));
    return outcome;
}

}  // namespace cambench::cli
