#include "e2e_support.h"

#include "test_pace.h"

#include <QFile>

#include <algorithm>

namespace cambench::e2e {

QStringList SimSession::protocolArgs() const {
    if (m_protocol.isEmpty()) return {};
    return {QStringLiteral("--protocol"), m_protocol};
}

QString SimSession::baud() const {
    return m_protocol == QLatin1String("cambus") ? kCamBusBaud : kFastBaud;
}

bool SimSession::start(const QStringList& simArgs) {
    // A Cam-BUS simulator waits the bus's T (10 ms) for the PC's answers
    // (no --pc-answer-ms), a display polls the first CamCon meanwhile, and
    // it logs the turns the PC let go by (--verbose).
    QStringList busArgs;
    if (m_protocol == QLatin1String("cambus")) {
        busArgs << QStringLiteral("--verbose");
        if (!simArgs.contains(QStringLiteral("--display")))
            busArgs << QStringLiteral("--display") << QStringLiteral("12");
    }
    return m_dir.isValid() && m_sim.start(QStringList{QStringLiteral("--baud"), baud()} +
                                              protocolArgs() + busArgs + simArgs,
                                          m_dir.filePath(QStringLiteral("sim-stderr.log")));
}

CliRun SimSession::cli(const QStringList& args, int timeoutMs) const {
    const QString log = m_dir.filePath(QStringLiteral("sim-stderr.log"));
    const qsizetype before = readBytes(log).size();
    CliRun run = runCli(
        QStringList{QStringLiteral("--port"), m_sim.ptyPath(), QStringLiteral("--baud"), baud()} +
            protocolArgs() + args,
        timeoutMs);
    if (m_protocol == QLatin1String("cambus")) {
        // The simulator's lines "the PC ... let N turn(s) in a row go by".
        for (const QString& line : QString::fromUtf8(readBytes(log).mid(before)).split('\n'))
            if (line.contains(QLatin1String("turn(s) in a row go by")))
                run.busMisses += line.section(QLatin1String("Cam-BUS: "), 1) + QLatin1Char('\n');
    }
    return run;
}

CliRun SimSession::cliMultiuser(const QStringList& args) const {
    return cli(QStringList{QStringLiteral("--protocol"), QStringLiteral("multiuser")} + args);
}

QByteArray readBytes(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

bool writeBytes(const QString& path, const QByteArray& bytes) {
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

namespace {
// The start of the Cam-BUS backend's sentence (CamBusBackend::latenessNote).
const QLatin1String kTooLate("the PC was too late to answer on the bus");
}  // namespace

bool tooSlowForTheBus(const CliRun& run) {
    return run.err.contains(kTooLate) || !run.busMisses.isEmpty();
}

QString tooSlowForTheBusText(const CliRun& run) {
    const qsizetype at = run.err.indexOf(kTooLate);
    if (at >= 0) return run.err.mid(at).section(QLatin1Char(')'), 0, 0) + QLatin1Char(')');
    return run.busMisses.section(QLatin1Char('\n'), 0, 0);
}

QByteArray describe(const CliRun& run) {
    return QStringLiteral("exit %1%2\nstdout: %3\nstderr: %4")
        .arg(run.exitCode)
        .arg(run.finished ? QString() : QStringLiteral(" (killed: hung)"), run.out, run.err)
        .toLocal8Bit();
}

}  // namespace cambench::e2e
