#include "interrupt_watch.h"

#include "comm/device/job_runner.h"

#include <QList>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <mutex>
#include <thread>

#include <unistd.h>

namespace cambench::cli {

namespace {

int g_pipe[2] = {-1, -1};  // [0] read by the watching thread, [1] written by the handler
std::atomic_int g_received{0};
std::mutex g_mutex;
QList<comm::JobRunner*> g_runners;

void onSignal(int signal) {
    const char byte = char(signal);
    [[maybe_unused]] const ssize_t written = ::write(g_pipe[1], &byte, 1);
}

void act(int signal) {
    // A second signal: the default action, at once.
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    g_received = signal;
    const QString cause = signal == SIGINT ? QStringLiteral("SIGINT") : QStringLiteral("SIGTERM");
    {
        std::lock_guard lock(g_mutex);
        for (comm::JobRunner* runner : g_runners) {
            runner->raiseStopGeneration(cause);
            runner->cancelAll();
        }
    }
    std::fprintf(stderr,
                 "cambench-cli: %s: nothing that moves or writes is sent from now on; what "
                 "was sent before stays done - an axis that moves still moves (stop it: "
                 "`mc axis all stop`, `c3 stop`, or the machine's emergency stop)\n",
                 qPrintable(cause));
}

}  // namespace

bool InterruptWatch::install() {
    if (g_pipe[0] >= 0) return true;
    if (::pipe(g_pipe) != 0) return false;
    std::thread([] {
        char byte = 0;
        while (::read(g_pipe[0], &byte, 1) == 1) act(int(byte));
    }).detach();
    struct sigaction action {};
    action.sa_handler = &onSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    return true;
}

int InterruptWatch::received() {
    return g_received.load();
}

void InterruptWatch::add(comm::JobRunner* runner) {
    std::lock_guard lock(g_mutex);
    g_runners.append(runner);
}

void InterruptWatch::remove(comm::JobRunner* runner) {
    std::lock_guard lock(g_mutex);
    g_runners.removeAll(runner);
}

}  // namespace cambench::cli
