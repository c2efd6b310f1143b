// Issue 14, end to end: the real cambench-cli against the real cambench-sim
// on a pseudo-terminal, for each MC100/MC200 variant: identification,
// variables, flags, I/O, memory, and backup → change → verify → restore →
// verify with honest counts.
#include "../child_process.h"
#include "../e2e_support.h"
#include "../test_pace.h"

#include <QProcess>

#include <csignal>

#include <signal.h>

#include <QTest>

using namespace cambench::e2e;

class TestE2eMc1 : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void eachVariant_data() {
        QTest::addColumn<QString>("variant");
        QTest::addColumn<QString>("name");
        QTest::newRow("mc100v1") << "mc100v1"
                                 << "MC100 V1";
        QTest::newRow("mc100v2") << "mc100v2"
                                 << "MC100 V2";
        QTest::newRow("mc200v1") << "mc200v1"
                                 << "MC200 V1";
        QTest::newRow("mc200v2") << "mc200v2"
                                 << "MC200 V2";
    }

    void eachVariant() {
        QFETCH(QString, variant);
        QFETCH(QString, name);
        const bool v2mc200 = variant == QLatin1String("mc200v2");
        SimSession session(QStringLiteral("mc1"));
        START_SIM(session, {"--variant", variant});

        const CliRun info = session.cli({"mc", "info"});
        VERIFY_EXIT(info, 0);
        QVERIFY2(info.out.contains(QStringLiteral("variant: %1\n").arg(name)),
                 qPrintable(info.out));
        QVERIFY2(info.out.contains(QLatin1String("found: probed")), qPrintable(info.out));

        VERIFY_EXIT(session.cli({"mc", "var", "write", "12", "-5"}), 0);
        const CliRun var = session.cli({"mc", "var", "read", "11-12"});
        VERIFY_EXIT(var, 0);
        QVERIFY2(var.out.endsWith(QLatin1String("V12 = -5\n")), qPrintable(var.out));

        const CliRun set = session.cli({"mc", "flag", "set", "M7", "A3", "M2327"});
        VERIFY_EXIT(set, 0);
        QCOMPARE(set.out, QStringLiteral("M7 = 1\nA3 = 1\nM2327 = 1\n"));
        const CliRun io = session.cli({"mc", "io", "read"});
        VERIFY_EXIT(io, 0);
        QVERIFY2(io.out.contains(QLatin1String("\nA3 = 1\n")), qPrintable(io.out.left(200)));
        QVERIFY2(io.out.contains(QLatin1String("E2 = 1\n")), qPrintable(io.out.left(200)));
        const CliRun input = session.cli({"mc", "flag", "set", "E2"});
        VERIFY_EXIT(input, 2);

        const CliRun run = session.cli({"mc", "run"});
        if (v2mc200) {
            VERIFY_EXIT(run, 0);
            QVERIFY2(run.out.startsWith(QLatin1String("program: running")), qPrintable(run.out));
            VERIFY_EXIT(session.cli({"mc", "mem", "write", "0x100", "0a0b0c"}), 0);
            const CliRun mem = session.cli({"mc", "mem", "read", "0x100", "3"});
            VERIFY_EXIT(mem, 0);
            QCOMPARE(mem.out, QStringLiteral("0x0100: 0a 0b 0c\n"));
        } else {
            VERIFY_EXIT(run, 1);  // no SYSDATA: the controller lacks it, nothing is sent
            QVERIFY2(run.err.contains(name), qPrintable(run.err));
        }

        // Backup, change, verify (differs), restore (only the changes), verify.
        const QString file = session.path(QStringLiteral("backup.json"));
        QStringList backup{"mc", "backup", "-o", file, "--vars", "1-40"};
        if (v2mc200)
            backup << "--mem"
                   << "0x100:200";
        VERIFY_EXIT(session.cli(backup), 0);
        VERIFY_EXIT(session.cli({"mc", "var", "write", "12", "77"}), 0);
        VERIFY_EXIT(session.cli({"mc", "flag", "clear", "M7"}), 0);
        if (v2mc200) VERIFY_EXIT(session.cli({"mc", "mem", "write", "0x101", "ff"}), 0);
        const CliRun differs = session.cli({"mc", "verify", file});
        VERIFY_EXIT(differs, 1);
        QVERIFY2(differs.out.contains(QStringLiteral("V12 -5 → 77")), qPrintable(differs.out));
        QVERIFY2(differs.out.contains(QStringLiteral("M7 1 → 0")), qPrintable(differs.out));
        const CliRun restore = session.cli({"mc", "restore", file});
        VERIFY_EXIT(restore, 0);
        const QString written = v2mc200 ? QStringLiteral("3 written") : QStringLiteral("2 written");
        QVERIFY2(restore.out.contains(written), qPrintable(restore.out));
        QVERIFY2(!restore.out.contains(QLatin1String("failed")), qPrintable(restore.out));
        VERIFY_EXIT(session.cli({"mc", "verify", file}), 0);
    }

    // Detect tries every family's protocols; an MC-1 controller is named
    // with its variant (at 9600 baud, the protocol's default).
    void detectFindsTheController() {
        SimProcess sim;
        QVERIFY2(sim.start({"--family", "mc1", "--variant", "mc200v1"}),
                 qPrintable(sim.errorText()));
        const CliRun detect = runCli({"--port", sim.ptyPath(), "detect"});
        VERIFY_EXIT(detect, 0);
        QVERIFY2(detect.out.contains(QLatin1String("mc1: MC200 V1 (probed)")),
                 qPrintable(detect.out));
    }

    // Issue 39, item 3: an MC100MA single-FIFO card (0xFF every 10 ms, a
    // telegram taken only right after one) is found by Detect as `mc info`
    // finds it, and by the same probe in the desktop application.
    void detectFindsAnMc100maCard() {
        SimProcess sim;
        QVERIFY2(sim.start({"--family", "mc1", "--variant", "mc100v1", "--sync", "10"}),
                 qPrintable(sim.errorText()));
        const CliRun info = runCli({"--port", sim.ptyPath(), "mc", "info"});
        VERIFY_EXIT(info, 0);
        const CliRun detect = runCli({"--port", sim.ptyPath(), "detect"});
        VERIFY_EXIT(detect, 0);
        QVERIFY2(detect.out.contains(QLatin1String("mc1: MC100 V1 (probed)")),
                 qPrintable(detect.out));
    }

    // An MC100 set to its ASCII protocol: variables, flags, a backup and a
    // restore of the differences; what ASCII lacks is refused by name; Detect
    // finds it after the binary protocols have been tried.
    void theMc100AsciiProtocol() {
        SimSession session(QStringLiteral("mc1-ascii"));
        START_SIM(session);
        const CliRun info = session.cli({"mc", "info"});
        VERIFY_EXIT(info, 0);
        QVERIFY2(info.out.contains(QLatin1String("found: ASCII protocol")), qPrintable(info.out));
        VERIFY_EXIT(session.cli({"mc", "var", "write", "4", "-8388608"}), 0);
        const CliRun var = session.cli({"mc", "var", "read", "4"});
        QCOMPARE(var.out, QStringLiteral("V4 = -8388608\n"));
        VERIFY_EXIT(session.cli({"mc", "var", "write", "4", "8388608"}), 2);
        const CliRun set = session.cli({"mc", "flag", "set", "M2327", "A9"});
        VERIFY_EXIT(set, 0);
        QCOMPARE(set.out, QStringLiteral("M2327 = 1\nA9 = 1\n"));
        const QString file = session.path(QStringLiteral("ascii.json"));
        VERIFY_EXIT(session.cli({"mc", "backup", "-o", file, "--vars", "1-8"}), 0);
        VERIFY_EXIT(session.cli({"mc", "flag", "clear", "M2327"}), 0);
        const CliRun restore = session.cli({"mc", "restore", file});
        VERIFY_EXIT(restore, 0);
        QVERIFY2(restore.out.contains(QLatin1String("M2327: written")), qPrintable(restore.out));
        VERIFY_EXIT(session.cli({"mc", "verify", file}), 0);
        const CliRun run = session.cli({"mc", "run"});
        VERIFY_EXIT(run, 1);
        QVERIFY2(run.err.contains(QLatin1String("ASCII protocol has no requests")),
                 qPrintable(run.err));
        const CliRun detect = runCli({"--port", session.ptyPath(), "detect"});
        VERIFY_EXIT(detect, 0);
        QVERIFY2(detect.out.contains(QLatin1String("mc1: MC100 (ASCII protocol)")),
                 qPrintable(detect.out));
    }

    // A file of the other controller type is refused before anything is sent.
    void aFileOfTheOtherControllerIsRefused() {
        SimSession mc200(QStringLiteral("mc1"));
        START_SIM(mc200, {"--variant", "mc200v2"});
        const QString file = mc200.path(QStringLiteral("mc200.json"));
        VERIFY_EXIT(mc200.cli({"mc", "backup", "-o", file, "--vars", "1-3"}), 0);
        SimSession mc100(QStringLiteral("mc1"));
        START_SIM(mc100, {"--variant", "mc100v1"});
        const CliRun refused = mc100.cli({"mc", "restore", file});
        VERIFY_EXIT(refused, 4);
        QVERIFY2(refused.err.contains(QLatin1String("another device answers")) &&
                     refused.err.contains(QLatin1String("variant mc200v2")) &&
                     refused.err.contains(QLatin1String("Nothing was written")),
                 qPrintable(refused.err));
        // Accepted as the replacement, the other widths still refuse it.
        const CliRun other = mc100.cli({"mc", "restore", file, "--replacement"});
        VERIFY_EXIT(other, 4);
        QVERIFY2(other.err.contains(QLatin1String("nothing was written")), qPrintable(other.err));
        // A variant named that does not answer so: refused, naming what answers.
        const CliRun wrong = mc100.cli({"--variant", "mc200v2", "mc", "var", "read", "1"});
        VERIFY_EXIT(wrong, 1);  // the controller is not the one named (issue 39)
        QVERIFY2(wrong.err.contains(QLatin1String("MC100 V1")), qPrintable(wrong.err));
    }

    // Issue 27: `mc axis all stop` on two controllers that differ (axes 1,
    // 2, 5 and all eight): one line per axis, exit 0 when every stop was
    // acknowledged; the stops go out before anything else. Issue 35: a
    // fresh `cambench-cli` knows neither the controller nor its axes, so
    // every axis an MC200 can have gets its stop, first - no probe, no
    // RDTABLE before them -, and the axes it lacks say "no such axis";
    // `--axes` names the axes instead.
    void stopOfEveryAxis() {
        SimSession three(QStringLiteral("mc1"));
        START_SIM(three, {"--axes", "1,2,5"});
        VERIFY_EXIT(three.cli({"mc", "axis", "5", "jog", "+"}), 0);
        const QString log = three.path(QStringLiteral("stop.log"));
        const CliRun stop = three.cli({"--log", log, "mc", "axis", "all", "stop"});
        VERIFY_EXIT(stop, 0);
        const QStringList lines = stop.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 8);
        QVERIFY2(lines.at(4).startsWith(QLatin1String("Axis 5: acknowledged; axis 5 stands at")),
                 qPrintable(stop.out));
        QVERIFY2(
            lines.at(2) == QLatin1String("Axis 3: no such axis: the controller refused its stop"),
            qPrintable(stop.out));
        QCOMPARE(stop.out.count(QLatin1String(": no such axis")), 5);
        // Every stop (9B) first: the first telegrams are the eight stops.
        QList<QByteArray> sent;
        for (const QByteArray& line : readBytes(log).split('\n'))
            if (line.contains(" > ")) sent << line.mid(line.indexOf(" > ") + 3, 2);
        QVERIFY2(sent.size() > 8, readBytes(log).constData());
        QCOMPARE(sent.mid(0, 8), QList<QByteArray>(8, "9B"));
        QVERIFY(!sent.contains("E5"));  // no RDTABLE

        const CliRun named = three.cli({"mc", "axis", "all", "stop", "--axes", "1,2,5"});
        VERIFY_EXIT(named, 0);
        QCOMPARE(named.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts).size(), 3);

        SimSession eight(QStringLiteral("mc1"));
        START_SIM(eight);
        const CliRun all = eight.cli({"mc", "axis", "all", "stop"});
        VERIFY_EXIT(all, 0);
        QCOMPARE(all.out.count(QLatin1String(": acknowledged;")), 8);
    }

    // A controller whose axis parameters are not CamBench's guess: the move
    // is acknowledged (exit 0, said as done) and the refused read-back is
    // said apart, naming the parameter and what to load; with the
    // controller's table loaded the axis is read, not provisional; a
    // malformed table is refused naming its line and nothing is sent.
    void anAcknowledgedMoveIsDoneWhateverItsReadBack() {
        SimSession session(QStringLiteral("mc1"));
        START_SIM(session, {"--parameter-base", "0x2000"});
        const CliRun moved = session.cli({"mc", "axis", "1", "move", "--rel", "100"});
        VERIFY_EXIT(moved, 0);
        QVERIFY2(moved.out.startsWith(QLatin1String("done: move axis 1 by 100 (acknowledged)\n")),
                 qPrintable(moved.out));
        QVERIFY2(moved.out.contains(QLatin1String("read-back: failed")), qPrintable(moved.out));
        QVERIFY2(moved.out.contains(QLatin1String("load the controller's parameter table")),
                 qPrintable(moved.out));

        const QString table = session.path(QStringLiteral("mc200.csv"));
        QVERIFY(writeBytes(table,
                           "name,axis,parameter\nposition,1,0x2010\ntarget,1,0x2011\n"
                           "status,1,0x2012\n"));
        const CliRun status = session.cli({"mc", "axis", "1", "status", "--parameters", table});
        VERIFY_EXIT(status, 0);
        QVERIFY2(status.out.contains(QLatin1String("position: 100\n")) ||
                     status.out.contains(QLatin1String("moving: 1\n")),
                 qPrintable(status.out));
        QVERIFY2(status.out.contains(QStringLiteral("parameters: %1\n").arg(table)),
                 qPrintable(status.out));
        QVERIFY2(!status.out.contains(QLatin1String("provisional")), qPrintable(status.out));

        const CliRun guessed = session.cli({"mc", "axis", "2", "status"});
        VERIFY_EXIT(guessed, 1);  // refused by the controller, said by name
        QVERIFY2(guessed.err.contains(QLatin1String("parameter 4128 (0x1020)")),
                 qPrintable(guessed.err));

        const QString bad = session.path(QStringLiteral("bad.csv"));
        QVERIFY(writeBytes(bad, "position,1,0x2010\nposition,one,5\n"));
        const QString log = session.path(QStringLiteral("bad.log"));
        const CliRun refused = session.cli(
            {"--log", log, "mc", "axis", "1", "move", "--rel", "5", "--parameters", bad});
        VERIFY_EXIT(refused, 4);
        QVERIFY2(refused.err.contains(QLatin1String("line 2: the axis must be 1 to 8")),
                 qPrintable(refused.err));
        QVERIFY2(!readBytes(log).contains(" > "), readBytes(log).constData());
    }

    // Every item of a multi-item write is checked before the first byte:
    // M99999 does not exist, so M2 is not written either.
    void aFlagWriteChecksEveryItemFirst() {
        SimSession session(QStringLiteral("mc1"));
        START_SIM(session);
        const QString log = session.path(QStringLiteral("flags.log"));
        const CliRun refused = session.cli({"--log", log, "mc", "flag", "set", "M2", "M99999"});
        VERIFY_EXIT(refused, 2);
        QVERIFY2(refused.err.contains(QLatin1String("nothing was written")),
                 qPrintable(refused.err));
        for (const QByteArray& line : readBytes(log).split('\n'))
            QVERIFY2(!line.contains(" > 3B ") && !line.contains(" > BB "), line.constData());
        const CliRun read = session.cli({"mc", "flag", "read", "M2"});
        QCOMPARE(read.out, QStringLiteral("M2 = 0\n"));
    }

    // Issue 35: SIGINT while `mc restore` writes. Decided: the signal is
    // not a STOP, but nothing that writes or moves leaves after it; the
    // write on the wire when it came is the last; stderr says what the
    // signal did; exit 130. The simulator answers after 400 ms, so the
    // signal lands while the first write waits for its answer.
    void anInterruptedRestoreSendsNoMoreWrites() {
        SimSession changed(QStringLiteral("mc1"));
        START_SIM(changed);
        for (int v = 1; v <= 5; ++v)
            VERIFY_EXIT(
                changed.cli({"mc", "var", "write", QString::number(v), QString::number(1000 + v)}),
                0);
        const QString file = changed.path(QStringLiteral("backup.json"));
        VERIFY_EXIT(changed.cli({"mc", "backup", "-o", file, "--vars", "1-5", "--no-flags"}), 0);

        SimSession slow(QStringLiteral("mc1"));
        START_SIM(slow, {"--delay", "400", "--verbose"});
        QProcess cli;
        cli.setProgram(QStringLiteral(CAMBENCH_CLI_EXE));
        cli.setArguments({"--port", slow.ptyPath(), "--baud", "115200", "--protocol", "mc1", "mc",
                          "restore", file});
        endWithThisTest(cli);
        cli.start();
        QVERIFY(cli.waitForStarted());
        const QString simLog = slow.path(QStringLiteral("sim-stderr.log"));
        // WRVAR (32 bit, CF) arrived at the controller: its answer comes in 400 ms.
        QVERIFY2(QTest::qWaitFor([&] { return readBytes(simLog).contains("<- cf"); },
                                 hangBoundMs(60000)),
                 readBytes(simLog).constData());
        QCOMPARE(::kill(pid_t(cli.processId()), SIGINT), 0);
        QVERIFY(cli.waitForFinished(hangBoundMs(60000)));
        const QByteArray err = cli.readAllStandardError();
        const QByteArray out = cli.readAllStandardOutput();
        QCOMPARE(cli.exitStatus(), QProcess::NormalExit);
        QVERIFY2(cli.exitCode() == 130, (out + err).constData());
        QVERIFY2(err.contains("SIGINT: nothing that moves or writes is sent from now on"),
                 err.constData());
        QTest::qWait(500);  // what the simulator received is all in its log
        QCOMPARE(readBytes(simLog).count("<- cf"), 1);
    }
};

QTEST_GUILESS_MAIN(TestE2eMc1)
#include "tst_e2e_mc1.moc"
