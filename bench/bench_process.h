#pragma once

#include <QProcess>
#include <QString>
#include <QStringList>

namespace cambench::bench {

// Starts cambench-sim with `args`, ending with the benchmark however it ends
// (tests/e2e/child_process.h, the tests' own helper); its pty path, or a
// fatal error.
QString startSim(QProcess& sim, const QStringList& args);

}  // namespace cambench::bench
