#include "child_process.h"

#include <QProcess>

#include <sys/prctl.h>
#include <unistd.h>
#include <csignal>

namespace cambench::e2e {

void endWithThisTest(QProcess& process) {
    const pid_t test = getpid();
    // Runs in the child between fork and exec: only async-signal-safe calls.
    process.setChildProcessModifier([test] {
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        // The test died before the line above took effect: no signal will
        // come, so the child ends itself instead of running on as an orphan.
        if (getppid() != test) _exit(127);
    });
}

}  // namespace cambench::e2e
