#include "sim_pty_server.h"

#include "sim_log.h"

#include <fcntl.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>

namespace cambench::comm {

namespace {

bool makeRaw(int fd) {
    termios tio{};
    if (tcgetattr(fd, &tio) != 0) return false;
    cfmakeraw(&tio);
    return tcsetattr(fd, TCSANOW, &tio) == 0;
}

QString systemError(const char* what) {
    return QStringLiteral("%1 failed: %2")
        .arg(QLatin1String(what), QString::fromLocal8Bit(std::strerror(errno)));
}

}  // namespace

SimPtyServer::SimPtyServer(SimEndpoint& line, const SimPacer& pacer, QObject* parent)
    : QObject(parent),
      m_scheduler(line, pacer, [this](const QByteArray& bytes) { write(bytes); }) {}

SimPtyServer::~SimPtyServer() {
    m_notifier.reset();
    if (m_slave >= 0) ::close(m_slave);
    if (m_master >= 0) ::close(m_master);
}

Status SimPtyServer::open() {
    char name[256] = {};
    if (openpty(&m_master, &m_slave, name, nullptr, nullptr) != 0) {
        return Error::communication(
            QStringLiteral("Cannot create a pseudo-terminal: %1.").arg(systemError("openpty")));
    }
    if (!makeRaw(m_master) || !makeRaw(m_slave)) {
        return Error::communication(QStringLiteral("Cannot make the pseudo-terminal raw: %1.")
                                        .arg(systemError("tcsetattr")));
    }
    fcntl(m_master, F_SETFL, fcntl(m_master, F_GETFL) | O_NONBLOCK);
    m_slavePath = QString::fromLocal8Bit(name);
    m_notifier = std::make_unique<QSocketNotifier>(m_master, QSocketNotifier::Read);
    connect(m_notifier.get(), &QSocketNotifier::activated, this, &SimPtyServer::onReadable);
    return success();
}

void SimPtyServer::onReadable() {
    char buffer[4096];
    for (;;) {
        const ssize_t n = ::read(m_master, buffer, sizeof buffer);
        if (n > 0) {
            m_scheduler.received(QByteArray(buffer, qsizetype(n)));
            continue;
        }
        if (n < 0 && errno == EINTR) continue;
        return;  // EAGAIN: all read
    }
}

void SimPtyServer::write(const QByteArray& bytes) {
    qsizetype done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(m_master, bytes.constData() + done, size_t(bytes.size() - done));
        if (n > 0) {
            done += n;
        } else if (n < 0 && errno == EINTR) {
            continue;
        } else {
            // Nobody reads the slave and its buffer is full: the bytes are
            // lost, as on a serial line without a listener.
            qCWarning(commSimLog) << "pty full, dropped" << bytes.size() - done << "reply bytes";
            return;
        }
    }
}

}  // namespace cambench::comm
