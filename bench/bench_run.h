#pragma once

#include "comm/engine/request_engine.h"
#include "comm/transport/transport.h"

#include <functional>

namespace cambench::bench {

// One measured piece of work: wall time, bytes both ways on the wire and
// requests, from the engine's counters.
struct Run {
    double seconds = 0;
    qint64 wire = 0;
    int requests = 0;
};

// Opens `transport`; a failure ends the benchmark (exit 3) with its message.
void openOrExit(comm::Transport& transport);
// Runs `work` with the engine's counters reset first; a failure ends the
// benchmark (exit 3) with its message.
Run timeWork(comm::RequestEngine& engine, const std::function<Status()>& work);

}  // namespace cambench::bench
