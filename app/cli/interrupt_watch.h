#pragma once

namespace cambench::comm {
class JobRunner;
}

namespace cambench::cli {

// SIGINT and SIGTERM while cambench-cli runs a command (issue 35). What is
// right, decided: the signal is not a STOP - it sends nothing the person
// did not ask for - but from the moment it arrives nothing of the command
// that moves or writes leaves, on every line the command uses (each device
// of a `machine` command too): each session's STOP generation is raised at
// once (comm/engine/stop_generation.h) and its jobs are cancelled. What had
// left stays done and is reported as the command reports any failure
// ("not sent: stopped before it moved: SIGINT at 14:02:11"); one line on
// stderr says what the signal did and that a moving axis still moves; the
// exit code is 128 + the signal's number (130, 143). A second signal ends
// the process at once (the default action).
class InterruptWatch {
public:
    // Starts watching (once, in main): the handler only writes the
    // signal's number to a pipe; a thread of its own reads it and acts,
    // whatever the main thread waits for.
    static bool install();
    // The signal that came (0: none).
    static int received();
    // Each session's job runner while it lives (any thread).
    static void add(comm::JobRunner* runner);
    static void remove(comm::JobRunner* runner);
};

}  // namespace cambench::cli
