#include "sim_process.h"

#include "child_process.h"
#include "test_pace.h"

#include <QDeadlineTimer>
#include <QDir>
#include <QFile>

namespace cambench::e2e {

namespace {

constexpr int kQuietStartBoundMs = 20000;

}  // namespace

SimProcess::~SimProcess() {
    stop();
}

bool SimProcess::start(const QStringList& args, const QString& stderrLog) {
    m_process.setProgram(QStringLiteral(CAMBENCH_SIM_EXE));
    m_process.setArguments(args);
    // Nobody reads the simulator's log while a test runs: a pipe could fill
    // up and stall it, so its stderr goes to a file (or nowhere).
    m_process.setStandardErrorFile(stderrLog.isEmpty() ? QProcess::nullDevice() : stderrLog);
    endWithThisTest(m_process);
    const int startBoundMs = hangBoundMs(kQuietStartBoundMs);
    m_process.start();
    if (!m_process.waitForStarted(startBoundMs)) {
        m_error = QStringLiteral("cambench-sim did not start: %1").arg(m_process.errorString());
        return false;
    }
    const QDeadlineTimer deadline(startBoundMs);
    while (!m_process.canReadLine()) {
        if (deadline.hasExpired() || m_process.state() != QProcess::Running) {
            m_error = QStringLiteral("cambench-sim printed no pty path (arguments: %1)")
                          .arg(args.join(u' '));
            stop();
            return false;
        }
        m_process.waitForReadyRead(100);
    }
    const QString pty = QString::fromUtf8(m_process.readLine()).trimmed();
    m_ptyPath = pty.isEmpty() || !m_linkFolder.isValid()
                    ? pty
                    : linkedPort(pty, m_linkFolder.path(), QStringLiteral("ttySIM"));
    return !m_ptyPath.isEmpty();
}

void SimProcess::stop() {
    if (m_process.state() == QProcess::NotRunning) return;
    m_process.kill();
    m_process.waitForFinished(5000);
}

QString linkedPort(const QString& ptyPath, const QString& folder, const QString& name) {
    const QString link = QDir(folder).filePath(name);
    QFile::remove(link);
    return QFile::link(ptyPath, link) ? link : ptyPath;
}

CliRun runCli(const QStringList& args, int timeoutMs) {
    return runProgram(QStringLiteral(CAMBENCH_CLI_EXE), args, timeoutMs);
}

CliRun runProgram(const QString& program, const QStringList& args, int timeoutMs,
                  const QString& workingDirectory) {
    QProcess process;
    process.setProgram(program);
    process.setArguments(args);
    if (!workingDirectory.isEmpty()) process.setWorkingDirectory(workingDirectory);
    endWithThisTest(process);
    process.start();
    CliRun run;
    run.finished = process.waitForStarted(hangBoundMs(10000)) &&
                   process.waitForFinished(hangBoundMs(timeoutMs));
    if (!run.finished) {
        process.kill();
        process.waitForFinished(5000);
    }
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    run.out = QString::fromUtf8(process.readAllStandardOutput());
    run.err = QString::fromUtf8(process.readAllStandardError());
    return run;
}

}  // namespace cambench::e2e
