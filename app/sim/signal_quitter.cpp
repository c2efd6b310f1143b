#include "signal_quitter.h"

#include <QCoreApplication>

#include <sys/socket.h>
#include <unistd.h>
#include <csignal>

namespace cambench {

namespace {
int g_pipe[2] = {-1, -1};  // [0] read by the notifier, [1] written by the handler
}  // namespace

SignalQuitter::SignalQuitter(QObject* parent) : QObject(parent) {
    if (::socketpair(AF_UNIX, SOCK_STREAM, 0, g_pipe) != 0) return;
    m_notifier = std::make_unique<QSocketNotifier>(g_pipe[0], QSocketNotifier::Read);
    connect(m_notifier.get(), &QSocketNotifier::activated, this, &SignalQuitter::onNotified);
    struct sigaction action {};
    action.sa_handler = &SignalQuitter::onSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGTERM, &action, nullptr);
    sigaction(SIGINT, &action, nullptr);
}

SignalQuitter::~SignalQuitter() {
    std::signal(SIGTERM, SIG_DFL);
    std::signal(SIGINT, SIG_DFL);
    m_notifier.reset();
    for (int& fd : g_pipe) {
        if (fd >= 0) ::close(fd);
        fd = -1;
    }
}

void SignalQuitter::onSignal(int signal) {
    const char byte = char(signal);
    [[maybe_unused]] const ssize_t written = ::write(g_pipe[1], &byte, 1);
}

void SignalQuitter::onNotified() {
    char byte = 0;
    [[maybe_unused]] const ssize_t n = ::read(g_pipe[0], &byte, 1);
    QCoreApplication::quit();
}

}  // namespace cambench
