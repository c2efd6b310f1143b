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
// A Cam-BUS run that failed while this machine could not answer within the
// bus's T (the cli or the simulator says so) skips: the bus is not widened for a slow
// machine, and a slow machine is no failure of CamBench. `run` is evaluated
// once: Qt 6.4's QVERIFY2 evaluates its message also when the check holds,
// so a command named twice there ran twice (a restore or write acted twice).
#define VERIFY_EXIT(run, code)                                                                \
    do {                                                                                      \
        const ::cambench::e2e::CliRun& verifiedRun = (run);                                   \
        if (verifiedRun.exitCode != (code) && ::cambench::e2e::tooSlowForTheBus(verifiedRun)) \
            QSKIP(qPrintable(QStringLiteral("this machine is too slow for the Cam-BUS's "     \
                                            "timing: %1")                                     \
                                 .arg(::cambench::e2e::tooSlowForTheBusText(verifiedRun))));  \
        QVERIFY2(verifiedRun.exitCode == (code),                                              \
                 ::cambench::e2e::describe(verifiedRun).constData());                         \
    } while (false)

namespace cambench::e2e {

// Fast lines keep the suite short; both ends must agree on the rate.
inline const QString kFastBaud = QStringLiteral("115200");
// The Cam-BUS runs at its own rate and timing (38400, T = 10 ms): a faster
// line would hide what its timing does (issue 39).
inline const QString kCamBusBaud = QStringLiteral("38400");

// One simulator on a pty and a scratch folder for the files of one test.
// With a protocol ("3964r-n96"), both the simulator and every cli() run
// speak it; without one, each side its default (Standard).
class SimSession {
public:
    explicit SimSession(QString protocol = {}) : m_protocol(std::move(protocol)) {}

    // `simArgs` are added to "--baud 115200" (Cam-BUS: 38400); false when
    // the sim did not start.
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
    QString baud() const;

    QString m_protocol;
    QTemporaryDir m_dir;
    SimProcess m_sim;
};

QByteArray readBytes(const QString& path);
bool writeBytes(const QString& path, const QByteArray& bytes);

// For QVERIFY2: the run's exit code, stdout and stderr.
QByteArray describe(const CliRun& run);

// Whether the PC was too late to answer on a Cam-BUS during the run (the
// cli's own words, or the turns the simulated users waited for it in vain),
// and the first such sentence.
bool tooSlowForTheBus(const CliRun& run);
QString tooSlowForTheBusText(const CliRun& run);

}  // namespace cambench::e2e
