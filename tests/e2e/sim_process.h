#pragma once

#include <QProcess>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>

namespace cambench::e2e {

// The real `cambench-sim` executable serving a pseudo-terminal. Killed when
// this object dies, and by the kernel when the test process dies (a timeout,
// a crash: endWithThisTest), so every test ends with its simulator gone.
class SimProcess {
public:
    SimProcess() = default;
    ~SimProcess();
    SimProcess(const SimProcess&) = delete;
    SimProcess& operator=(const SimProcess&) = delete;

    // Starts the simulator with `args` and waits (bounded) for the pty path
    // on its first stdout line. False, with errorText(), when it did not start.
    // The simulator's stderr goes to `stderrLog` when given.
    bool start(const QStringList& args, const QString& stderrLog = {});
    void stop();

    // The port to give the cli: a link of this object's own to the pty
    // (linkedPort()).
    QString ptyPath() const { return m_ptyPath; }
    qint64 processId() const { return m_process.processId(); }
    QString errorText() const { return m_error; }

private:
    QProcess m_process;
    QTemporaryDir m_linkFolder;
    QString m_ptyPath;
    QString m_error;
};

// A name of its own for the pseudo-terminal `ptyPath`: the link
// `folder`/`name` to it, or `ptyPath` itself when no link can be made.
// QSerialPort locks a port by its name (/var/lock/LCK..pts_2), and pty
// numbers are handed out again. Under parallel tests a cli was refused the
// /dev/pts/2 of its test's new simulator ("Permission error while locking
// the device"): a lock of that name was still held. A link's name is the
// test's alone; the cli opens the pty through it.
QString linkedPort(const QString& ptyPath, const QString& folder, const QString& name);

// One run of the real `cambench-cli` executable.
struct CliRun {
    int exitCode = -1;
    bool finished = false;  // false: it had to be killed (hang)
    QString out;
    QString err;
    // On a simulated Cam-BUS: the turns the simulated users waited for the
    // PC in vain meanwhile, as the simulator logged them (empty: none).
    QString busMisses;
};

// Runs cambench-cli with `args`, bounded by `timeoutMs` on a quiet machine
// (a hang bound, not a performance limit), stretched by testPace().
CliRun runCli(const QStringList& args, int timeoutMs = 120000);
// The same for another program (cambench-sim when it is to refuse), in
// `workingDirectory` when given.
CliRun runProgram(const QString& program, const QStringList& args, int timeoutMs = 120000,
                  const QString& workingDirectory = {});

}  // namespace cambench::e2e
