// Issue 37: a machine's history against three simulators on ptys - a
// CamCon, an MC200 (mc200v2) and a Compax3, each a real cambench-sim. Two
// versions archived with a change on each device between them; a third
// backup with no change makes no version; `machine history` names the
// changes; `machine diff` gives them per device in each family's terms;
// the first released, `machine watch` exits 1 naming exactly the changed
// devices; a change of a volatile MC-1 variable alone exits 0; the
// released version restored, watch exits 0; a change of the drive alone
// names only it, and --commit stores it; a device not reached exits 3;
// plain `git log` and `git show` read the archive.
#include "e2e_support.h"
#include "press_machine.h"

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTest>

#include <sys/types.h>
#include <csignal>

using namespace cambench::e2e;

namespace {

// Plain git in the archive, as a person would run it (no configuration of
// theirs needed): what it printed.
QString git(const QString& dir, const QStringList& args) {
    QProcess process;
    process.start(QStringLiteral("git"), QStringList{QStringLiteral("-C"), dir} + args);
    process.waitForFinished(60000);
    return QString::fromUtf8(process.readAllStandardOutput());
}

// "version 0123456789 stored": the id.
QString storedId(const QString& out) {
    const QRegularExpressionMatch match =
        QRegularExpression(QStringLiteral("version ([0-9a-f]{10}) stored")).match(out);
    return match.captured(1);
}

}  // namespace

class TestE2eMachineHistory : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void versionsReleasedAndWatched() {
        SimSession cams;
        SimSession plc(QStringLiteral("mc1"));
        SimSession feed(QStringLiteral("compax3"));
        startPress(cams, plc, feed, {"--outputs", "16"});
        if (QTest::currentTestFailed()) return;
        const QString file = cams.path(QStringLiteral("press7.json"));
        QVERIFY(writeBytes(
            file, pressMachineFile(cams.ptyPath(), plc.ptyPath(), feed.ptyPath(), {"V100-V199"})));
        const QString archive = cams.path(QStringLiteral("press7-archive"));  // made by the backup

        const CliRun first = runCli({"machine", "backup", file, "--archive", archive, "-m",
                                     "commissioning", "--operator", "alice"});
        VERIFY_EXIT(first, 0);
        const QString firstId = storedId(first.out);
        QVERIFY2(!firstId.isEmpty(), describe(first).constData());

        // One change on each device behind CamBench's back.
        const QString one = cams.path(QStringLiteral("one.csv"));
        QVERIFY(writeBytes(one, "output,cam,on,off\n1,1,100,120\n"));
        VERIFY_EXIT(cams.cli({"cams", "write", "--program", "0", one}), 0);
        VERIFY_EXIT(plc.cli({"mc", "var", "write", "12", "77"}), 0);
        VERIFY_EXIT(feed.cli({"c3", "write", "1901.1=12.5"}), 0);
        const CliRun second = runCli({"machine", "backup", file, "--archive", archive, "-m",
                                      "new glue pattern", "--operator", "bob"});
        VERIFY_EXIT(second, 0);
        const QString secondId = storedId(second.out);
        QVERIFY2(!secondId.isEmpty() && secondId != firstId, describe(second).constData());

        // Nothing changed: no third version, said.
        const CliRun third = runCli({"machine", "backup", file, "--archive", archive, "-m",
                                     "nightly", "--operator", "carol"});
        VERIFY_EXIT(third, 0);
        QVERIFY2(third.out.contains(QLatin1String("nothing changed since version ")) &&
                     third.out.contains(QLatin1String("no new version stored")),
                 describe(third).constData());
        QCOMPARE(git(archive, {"rev-list", "--count", "HEAD"}).trimmed(), QStringLiteral("2"));
        QCOMPARE(git(archive, {"status", "--porcelain"}), QString());  // the latest again

        // The history: who, why, and a line per changed device.
        const CliRun history = runCli({"machine", "history", archive});
        VERIFY_EXIT(history, 0);
        const QString& h = history.out;
        QVERIFY2(h.indexOf(secondId) >= 0 && h.indexOf(secondId) < h.indexOf(firstId),
                 qPrintable(h));  // newest first
        for (const char* expected :
             {"bob  new glue pattern", "alice  commissioning", "    cams: program 0",
              "    plc: V12 0 → 77", "    feed: 1901.1", "    cams: added (first version: "})
            QVERIFY2(h.contains(QString::fromUtf8(expected)), qPrintable(expected + ("\n" + h)));

        // The differences of the last change, per device in its family's terms.
        const CliRun diff = runCli({"machine", "diff", archive});
        VERIFY_EXIT(diff, 1);
        for (const char* expected : {"cams: program 0, output 1", "plc: V12 0 → 77", "feed: 1901.1",
                                     "cams: DIFFERS", "plc: DIFFERS (1)", "feed: DIFFERS (1)"})
            QVERIFY2(diff.out.contains(QString::fromUtf8(expected)),
                     qPrintable(expected + ("\n" + diff.out)));
        VERIFY_EXIT(runCli({"machine", "diff", archive, firstId.left(7), firstId}), 0);

        // The first released: the devices now differ from it, each named.
        VERIFY_EXIT(runCli({"machine", "release", archive, firstId.left(7), "--operator", "dave"}),
                    0);
        const CliRun watched = runCli({"machine", "watch", archive});
        VERIFY_EXIT(watched, 1);
        QVERIFY2(watched.out.contains(QLatin1String("cams: DIFFERS")) &&
                     watched.out.contains(QLatin1String("plc: DIFFERS (1)")) &&
                     watched.out.contains(QLatin1String("feed: DIFFERS (1)")),
                 describe(watched).constData());

        // The released version restored: the devices are as released.
        const CliRun restored = runCli({"machine", "restore", archive, "--version", "released"});
        VERIFY_EXIT(restored, 0);
        QVERIFY2(restored.out.contains(QLatin1String("cams: restored\nplc: restored\nfeed: "
                                                     "restored")),
                 describe(restored).constData());
        const CliRun same = runCli({"machine", "watch", archive});
        VERIFY_EXIT(same, 0);
        QVERIFY2(same.out.contains(QLatin1String("cams: equal\nplc: equal\nfeed: equal")),
                 describe(same).constData());

        // A counter among the volatile variables changes: no difference.
        VERIFY_EXIT(plc.cli({"mc", "var", "write", "150", "4711"}), 0);
        const CliRun counted = runCli({"machine", "watch", archive});
        VERIFY_EXIT(counted, 0);
        QVERIFY2(counted.out.contains(QLatin1String("plc: equal (1 changes of volatile items "
                                                    "left out)")),
                 describe(counted).constData());

        // The drive alone changes: only it is named; --commit stores it.
        VERIFY_EXIT(feed.cli({"c3", "write", "1901.1=7.5"}), 0);
        const CliRun drive =
            runCli({"machine", "watch", archive, "--commit", "--operator", "night-watch"});
        VERIFY_EXIT(drive, 1);
        QVERIFY2(drive.out.contains(QLatin1String("cams: equal\nplc: equal (1 changes of "
                                                  "volatile items left out)\nfeed: DIFFERS (1)")),
                 describe(drive).constData());
        const QString watchId = storedId(drive.out);
        QVERIFY2(!watchId.isEmpty(), describe(drive).constData());
        QVERIFY(git(archive, {"log", "-1", "--format=%an|%cn"}).startsWith("night-watch|CamBench"));

        // Plain git reads the archive: the authors, the why, the files.
        QCOMPARE(git(archive, {"log", "--format=%an|%s"}),
                 QStringLiteral("night-watch|machine watch: differs from the released version "
                                "%1\nbob|new glue pattern\nalice|commissioning\n")
                     .arg(firstId));
        const QString shown = git(archive, {"show", "--stat", secondId});
        for (const char* part : {"new glue pattern", "Changed:", "plc: V12 0 → 77", "cams.json",
                                 "plc.json", "feed.json", "manifest.json"})
            QVERIFY2(shown.contains(QString::fromUtf8(part)), qPrintable(part + ("\n" + shown)));
        QVERIFY(git(archive, {"tag", "--list"}).contains(QLatin1String("released-1")));

        // A device not reached: exit 3, named.
        QCOMPARE(::kill(pid_t(plc.simulatorPid()), SIGKILL), 0);
        QTest::qWait(200);  // the pty closes with the process
        const CliRun unreachable = runCli({"machine", "watch", archive});
        VERIFY_EXIT(unreachable, 3);
        // Why in the backup's words, not as a temporary folder now removed.
        QVERIFY2(unreachable.out.contains(
                     QLatin1String("plc: NOT REACHED: its backup now failed: not reached: ")),
                 describe(unreachable).constData());
    }
};

QTEST_GUILESS_MAIN(TestE2eMachineHistory)
#include "tst_e2e_machine_history.moc"
