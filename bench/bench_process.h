#pragma once

#include <QProcess>
#include <QString>
#include <QStringList>

namespace cambench::bench {

// The real programs, as a person runs them: the benchmark starts them and
// they die with it, however it ends.
void dieWithBenchmark(QProcess& process);
// Starts cambench-sim with `args`; its pty path, or a fatal error.
QString startSim(QProcess& sim, const QStringList& args);

}  // namespace cambench::bench
