#pragma once

#include "child_process.h"
#include "sim_process.h"
#include "test_pace.h"

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>

// Test steps of every end-to-end test: start a simulator, check an exit code
// (the run's output in the message when it differs).
#define START_SIM(session, ...) \
    QVERIFY2((session).start(__VA_ARGS__), qPrintable((session).errorText()))
// The run is evaluated once: Qt 6.4's QVERIFY2 evaluates its message also
// when the check holds, so a command named twice there ran twice (and a
// restore or write in it acted twice).
#define VERIFY_EXIT(run, code)                                                         \
    do {                                                                               \
        const auto& verifiedRun_ = (run);                                              \
        QVERIFY2(verifiedRun_.exitCode == (code), describe(verifiedRun_).constData()); \
    } while (false)

namespace cambench::e2e {

// Fast lines keep the suite short; both ends must agree on the rate.
inline const QString kFastBaud = QStringLiteral("115200");

// One simulator on a pty and a scratch folder for the files of one test.
// With a protocol ("3964r-n96"), both the simulator and every cli() run
// speak it; without one, each side its default (Standard).
class SimSession {
public:
    explicit SimSession(QString protocol = {}) : m_protocol(std::move(protocol)) {}

    // `simArgs` are added to "--baud 115200"; false when the sim did not start.
    bool start(const QStringList& simArgs = {});
    QString errorText() const { return m_sim.errorText(); }
    QString ptyPath() const { return m_sim.ptyPath(); }
    qint64 simulatorPid() const { return m_sim.processId(); }

    // cambench-cli with --port <pty> --baud 115200 and then `args`; `timeoutMs`
    // as runCli's.
    CliRun cli(const QStringList& args, int timeoutMs = 120000) const;
    // The same with the Multiuser protocol.
    CliRun cliMultiuser(const QStringList& args) const;

    QString path(const QString& name) const { return m_dir.filePath(name); }

private:
    QStringList protocolArgs() const;

    QString m_protocol;
    QTemporaryDir m_dir;
    SimProcess m_sim;
};

QByteArray readBytes(const QString& path);
bool writeBytes(const QString& path, const QByteArray& bytes);

// For QVERIFY2: the run's exit code, stdout and stderr.
QByteArray describe(const CliRun& run);

}  // namespace cambench::e2e
