#pragma once

class QProcess;

namespace cambench::e2e {

// Makes `process` (set up, not started yet) end with this test process:
// the kernel kills it when the test dies, however it dies - QtTest's
// watchdog (an abort), CTest's TIMEOUT (a kill), a crash. Without this a
// timed-out test left its Cam-BUS simulator running, orphaned, using CPU.
// Call it for every program a test starts; the benchmark (bench/) calls it
// too (the library cambench_child_process, tests/CMakeLists.txt). The
// test's function must start the program on the main thread (QtTest runs
// its functions there): Linux ties the signal to the thread that started
// the child.
void endWithThisTest(QProcess& process);

}  // namespace cambench::e2e
