#include "e2e_support.h"

#include "test_pace.h"

#include <QFile>

#include <algorithm>

namespace cambench::e2e {

namespace {

constexpr int kQuietPcAnswerMs = 60;
constexpr int kMostPcAnswerMs = 1000;

}  // namespace

QStringList SimSession::protocolArgs() const {
    if (m_protocol.isEmpty()) return {};
    return {QStringLiteral("--protocol"), m_protocol};
}

bool SimSession::start(const QStringList& simArgs) {
    QStringList busArgs;
    // The bus waits 10 ms for the PC's answers; a loaded test machine (two
    // test processes, sanitizers) can take longer to schedule the cli: 60 ms
    // on a quiet machine, stretched by the measured pace (the sim takes 1000
    // at most).
    if (m_protocol == QLatin1String("cambus"))
        busArgs = {QStringLiteral("--pc-answer-ms"),
                   QString::number(std::min(hangBoundMs(kQuietPcAnswerMs), kMostPcAnswerMs))};
    return m_dir.isValid() && m_sim.start(QStringList{QStringLiteral("--baud"), kFastBaud} +
                                              protocolArgs() + busArgs + simArgs,
                                          m_dir.filePath(QStringLiteral("sim-stderr.log")));
}

CliRun SimSession::cli(const QStringList& args, int timeoutMs) const {
    return runCli(QStringList{QStringLiteral("--port"), m_sim.ptyPath(), QStringLiteral("--baud"),
                              kFastBaud} +
                      protocolArgs() + args,
                  timeoutMs);
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

QByteArray describe(const CliRun& run) {
    return QStringLiteral("exit %1%2\nstdout: %3\nstderr: %4")
        .arg(run.exitCode)
        .arg(run.finished ? QString() : QStringLiteral(" (killed: hung)"), run.out, run.err)
        .toLocal8Bit();
}

}  // namespace cambench::e2e
