#include "bench_process.h"

#include "tests/e2e/child_process.h"

namespace cambench::bench {

QString startSim(QProcess& sim, const QStringList& args) {
    sim.setProgram(QStringLiteral(CAMBENCH_SIM_EXE));
    sim.setArguments(args);
    sim.setProcessChannelMode(QProcess::SeparateChannels);
    e2e::endWithThisTest(sim);
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
