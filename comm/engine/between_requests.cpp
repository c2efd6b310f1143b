#include "between_requests.h"

namespace cambench::comm {

namespace {
thread_local BetweenRequests::Hook t_hook;
}  // namespace

void BetweenRequests::install(Hook hook) {
    t_hook = std::move(hook);
}

void BetweenRequests::run() {
    if (t_hook) t_hook();
}

}  // namespace cambench::comm
