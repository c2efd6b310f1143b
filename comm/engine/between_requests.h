#pragma once

#include <functional>

namespace cambench::comm {

// The clean point between two requests: RequestEngine::send() calls run()
// before anything of a request is sent, where no protocol exchange is half
// done. A thread that runs jobs on a line (the worker) installs what must
// not wait for a running job's end there: its urgent jobs, a STOP. Per
// thread, as every engine call of a job runs on the worker's thread; a
// thread without a hook (a test driving an engine itself) runs nothing.
class BetweenRequests {
public:
    using Hook = std::function<void()>;
    // For the calling thread; an empty hook removes it.
    static void install(Hook hook);
    static void run();
};

}  // namespace cambench::comm
