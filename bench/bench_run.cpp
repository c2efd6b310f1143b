#include "bench_run.h"

#include <QElapsedTimer>

#include <cstdio>
#include <cstdlib>

namespace cambench::bench {

void openOrExit(comm::Transport& transport) {
    if (Status opened = transport.open(); !opened) {
        std::fprintf(stderr, "cambench-bench: %s\n", qPrintable(opened.error().message));
        std::exit(3);
    }
}

Run timeWork(comm::RequestEngine& engine, const std::function<Status()>& work) {
    engine.resetStats();
    QElapsedTimer timer;
    timer.start();
    if (Status done = work(); !done) {
        std::fprintf(stderr, "cambench-bench: %s\n", qPrintable(done.error().message));
        std::exit(3);
    }
    const comm::RequestEngine::Stats& stats = engine.stats();
    return {timer.nsecsElapsed() / 1e9, stats.bytesSent + stats.bytesReceived, stats.requests};
}

}  // namespace cambench::bench
