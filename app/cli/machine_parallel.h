#pragma once

#include "cli_options.h"

#include <QList>

#include <functional>

namespace cambench::cli {

// Runs `work(i)` for each device index in `indices` (into `options`, the
// machine's devices in the file's order): devices that share a port (an
// RS485 bus, a device server's port) one after the other in the order
// given, different ports at once, each port on a thread of its own. `work`
// makes its own CliSession (its own worker) on that thread and keeps its
// result in a slot of its own. What it prints is held and printed whole,
// in the order of `indices`, so that no two devices' lines interleave.
// `done(i)` runs on the calling thread as soon as device i is finished,
// one device at a time (the backup rewrites its manifest there).
void runDevicesByPort(const QList<GlobalOptions>& options, const QList<int>& indices,
                      const std::function<void(int)>& work,
                      const std::function<void(int)>& done = {});

}  // namespace cambench::cli
