#include "bench_process.h"

#ifdef Q_OS_LINUX
#include <sys/prctl.h>
#include <csignal>
#endif

namespace cambench::bench {

void dieWithBenchmark(QProcess& process) {
#ifdef Q_OS_LINUX
    process.setChildProcessModifier([] { prctl(PR_SET_PDEATHSIG, SIGKILL); });
#else
    Q_UNUSED(process);
#endif
}

QString startSim(QProcess& sim, const QStringList& args) {
    sim.setProgram(QStringLiteral(CAMBENCH_SIM_EXE));
    sim.setArguments(args);
    sim.setProcessChannelMode(QProcess::SeparateChannels);
    dieWithBenchmark(sim);
    sim.start();
    while (!sim.canReadLine() && sim.waitForReadyRead(10000)) {
    }
    const QString path = QString::fromUtf8(sim.readLine()).trimmed();
    if (path.isEmpty())
        qFatal("cambench-sim %s did not start: %s", qPrintable(args.join(' ')),
               sim.readAllStandardError().constData());
    return path;
}

}  // namespace cambench::bench
