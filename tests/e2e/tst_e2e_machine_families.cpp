// Issue 30, items 3 and 6: a machine of three families on three
// pseudo-terminals - a CamCon, an MC200 (mc200v2) and a Compax3, each a real
// cambench-sim - backed up, verified and restored by `cambench-cli machine`,
// which takes devices on different ports at once. Each device's lines come
// whole and in the file's order; one value changed on each device behind
// CamBench's back makes verify exit 1 naming all three; a drive that refuses
// one object midway its backup leaves the others saved, and --resume then
// asks only that drive (the CamCon's simulator logs every request: none).
// A CamCon whose simulator is killed midway is the only one resumed too.
// Two names for one port (a path and a link to it) are asked one after the
// other.
#include "e2e_support.h"
#include "press_machine.h"

#include <QDeadlineTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>

#include <sys/types.h>
#include <csignal>

using namespace cambench::e2e;

namespace {

QJsonArray manifestDevices(const QString& dir) {
    return QJsonDocument::fromJson(readBytes(dir + QStringLiteral("/manifest.json")))
        .object()
        .value(QStringLiteral("devices"))
        .toArray();
}

QJsonObject entryOf(const QJsonArray& devices, const QString& name) {
    for (const QJsonValue& value : devices)
        if (value.toObject().value(QStringLiteral("name")).toString() == name)
            return value.toObject();
    return {};
}

// Requests the CamCon simulator logged (--verbose: one "<-" line each).
int camconRequests(const SimSession& session) {
    return int(readBytes(session.path(QStringLiteral("sim-stderr.log"))).count("<-"));
}

// Each device's block starts with "== NAME": the blocks in the file's order.
bool inFileOrder(const QString& out, const QStringList& names) {
    qsizetype last = -1;
    for (const QString& name : names) {
        const qsizetype at = out.indexOf(QStringLiteral("== %1").arg(name));
        if (at <= last) return false;
        last = at;
    }
    return true;
}

}  // namespace

class TestE2eMachineFamilies : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void threeFamiliesBackupVerifyRestore() {
        SimSession cams;
        SimSession plc(QStringLiteral("mc1"));
        SimSession feed(QStringLiteral("compax3"));
        startPress(cams, plc, feed, {"--outputs", "16"}, {});
        if (QTest::currentTestFailed()) return;
        const QString file = cams.path(QStringLiteral("press7.json"));
        QVERIFY(writeBytes(file, pressMachineFile(cams.ptyPath(), plc.ptyPath(), feed.ptyPath())));
        const QString dir = cams.path(QStringLiteral("press7-backup"));

        const CliRun status = runCli({"machine", "status", file});
        VERIFY_EXIT(status, 0);
        const QStringList lines = status.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 4);
        QVERIFY2(lines.at(1).startsWith(QStringLiteral("cams\tcamcon\t")) &&
                     lines.at(1).contains(QLatin1String("03.05.2001")),
                 qPrintable(status.out));
        QVERIFY2(lines.at(2).startsWith(QStringLiteral("plc\tmc1\t")) &&
                     lines.at(2).contains(QLatin1String("MC200")),
                 qPrintable(status.out));
        QVERIFY2(lines.at(3).startsWith(QStringLiteral("feed\tcompax3\t")) &&
                     lines.at(3).contains(QLatin1String("S150V4")),
                 qPrintable(status.out));

        const CliRun backup = runCli({"machine", "backup", file, "-o", dir});
        VERIFY_EXIT(backup, 0);
        QVERIFY2(backup.out.contains(QLatin1String("3 of 3 devices saved")),
                 describe(backup).constData());
        QVERIFY2(inFileOrder(backup.out, {"cams", "plc", "feed"}), qPrintable(backup.out));
        const QJsonArray saved = manifestDevices(dir);
        QCOMPARE(saved.size(), 3);
        for (const QJsonValue& entry : saved)
            QCOMPARE(entry.toObject().value("result").toString(), QStringLiteral("saved"));
        VERIFY_EXIT(runCli({"machine", "verify", dir}), 0);

        // One value on each device changes behind CamBench's back.
        const QString one = cams.path(QStringLiteral("one.csv"));
        QVERIFY(writeBytes(one, "output,cam,on,off\n1,1,100,120\n"));
        VERIFY_EXIT(cams.cli({"cams", "write", "--program", "0", one}), 0);
        VERIFY_EXIT(plc.cli({"mc", "var", "write", "12", "77"}), 0);
        VERIFY_EXIT(feed.cli({"c3", "write", "1901.1=12.5"}), 0);
        const CliRun differs = runCli({"machine", "verify", dir});
        VERIFY_EXIT(differs, 1);
        QVERIFY2(differs.out.contains(
                     QLatin1String("cams: DIFFERS (3)\nplc: DIFFERS (1)\nfeed: DIFFERS (1)")),
                 qPrintable(differs.out));
        QVERIFY2(inFileOrder(differs.out, {"cams", "plc", "feed"}), qPrintable(differs.out));

        const CliRun restore = runCli({"machine", "restore", dir});
        VERIFY_EXIT(restore, 0);
        QVERIFY2(
            restore.out.contains(QLatin1String("cams: restored\nplc: restored\nfeed: restored")),
            qPrintable(restore.out));
        const CliRun equal = runCli({"machine", "verify", dir});
        VERIFY_EXIT(equal, 0);
        QVERIFY2(equal.out.contains(QLatin1String("cams: equal\nplc: equal\nfeed: equal")),
                 qPrintable(equal.out));
    }

    // The drive refuses one object of its parameter set (!0005) midway its
    // backup: the CamCon and the MC200 are saved all the same, the drive is
    // named. A drive that answers then: --resume asks only it.
    void aDeviceFailingMidwayIsTheOnlyOneResumed() {
        SimSession cams;
        SimSession plc(QStringLiteral("mc1"));
        SimSession refusing(QStringLiteral("compax3"));
        startPress(cams, plc, refusing, {"--verbose"}, {"--refuse", "1901.1"});
        if (QTest::currentTestFailed()) return;
        const QString file = cams.path(QStringLiteral("press7.json"));
        QVERIFY(
            writeBytes(file, pressMachineFile(cams.ptyPath(), plc.ptyPath(), refusing.ptyPath())));
        const QString dir = cams.path(QStringLiteral("press7-backup"));

        const CliRun failed = runCli({"machine", "backup", file, "-o", dir});
        VERIFY_EXIT(failed, 3);
        QVERIFY2(
            failed.out.contains(QLatin1String("2 of 3 devices saved")) &&
                failed.out.contains(QLatin1String(
                    "NOT SAVED: feed: failed: incomplete: 1901.1: not saved: the drive refused")),
            describe(failed).constData());
        const QJsonArray first = manifestDevices(dir);
        QCOMPARE(first.size(), 3);
        QCOMPARE(entryOf(first, "cams").value("result").toString(), QStringLiteral("saved"));
        QCOMPARE(entryOf(first, "plc").value("result").toString(), QStringLiteral("saved"));
        QVERIFY(entryOf(first, "feed").value("result").toString().startsWith("failed"));
        const int camsAsked = camconRequests(cams);
        QVERIFY(camsAsked > 0);

        SimSession feed(QStringLiteral("compax3"));
        START_SIM(feed, {"--drive-type", "S150V4"});
        QVERIFY(writeBytes(file, pressMachineFile(cams.ptyPath(), plc.ptyPath(), feed.ptyPath())));
        const CliRun resumed = runCli({"machine", "backup", file, "-o", dir, "--resume"});
        VERIFY_EXIT(resumed, 0);
        QVERIFY2(resumed.out.contains(QLatin1String("== cams: kept from the earlier run")) &&
                     resumed.out.contains(QLatin1String("== plc: kept from the earlier run")) &&
                     resumed.out.contains(QLatin1String("== feed (compax3")) &&
                     resumed.out.contains(QLatin1String("3 of 3 devices saved")),
                 describe(resumed).constData());
        QCOMPARE(camconRequests(cams), camsAsked);  // the CamCon was not asked again
        const QJsonArray second = manifestDevices(dir);
        QCOMPARE(second.size(), 3);
        for (const char* kept : {"cams", "plc"})  // the earlier run's entries, as they were
            QCOMPARE(entryOf(second, kept), entryOf(first, kept));
        QCOMPARE(entryOf(second, "feed").value("result").toString(), QStringLiteral("saved"));
        VERIFY_EXIT(runCli({"machine", "verify", dir}), 0);
    }

    // The CamCon's simulator is killed midway its EEPROM backup (after its
    // tenth request): the CamCon is named not saved, the MC200 and the drive
    // are saved all the same. Another CamCon simulator then: --resume asks
    // only it, the others' entries stay as the first run wrote them.
    void aLineDyingMidwayLeavesTheOthersSaved() {
        SimSession cams;
        SimSession plc(QStringLiteral("mc1"));
        SimSession feed(QStringLiteral("compax3"));
        startPress(cams, plc, feed, {"--fill", "1", "--verbose"}, {});
        if (QTest::currentTestFailed()) return;
        const QString file = cams.path(QStringLiteral("press7.json"));
        QVERIFY(writeBytes(file, pressMachineFile(cams.ptyPath(), plc.ptyPath(), feed.ptyPath())));
        const QString dir = cams.path(QStringLiteral("press7-backup"));

        QProcess backup;
        backup.setProgram(QStringLiteral(CAMBENCH_CLI_EXE));
        backup.setArguments({"machine", "backup", file, "-o", dir});
        endWithThisTest(backup);
        backup.start();
        QVERIFY(backup.waitForStarted(hangBoundMs(10000)));
        QDeadlineTimer bound(hangBoundMs(60000));
        while (camconRequests(cams) < 10 && backup.state() == QProcess::Running &&
               !bound.hasExpired())
            backup.waitForFinished(10);
        QVERIFY2(camconRequests(cams) >= 10, "the CamCon's backup did not start");
        QCOMPARE(::kill(pid_t(cams.simulatorPid()), SIGKILL), 0);
        QVERIFY(backup.waitForFinished(hangBoundMs(120000)));
        const QString out = QString::fromUtf8(backup.readAllStandardOutput());
        QCOMPARE(backup.exitCode(), 3);
        QVERIFY2(out.contains(QLatin1String("2 of 3 devices saved")) &&
                     out.contains(QLatin1String("NOT SAVED: cams: failed")),
                 qPrintable(out));
        const QJsonArray first = manifestDevices(dir);
        QCOMPARE(first.size(), 3);
        QCOMPARE(entryOf(first, "plc").value("result").toString(), QStringLiteral("saved"));
        QCOMPARE(entryOf(first, "feed").value("result").toString(), QStringLiteral("saved"));

        SimSession again;
        START_SIM(again, {"--eprom", "03.05.2001", "--verbose"});
        QVERIFY(writeBytes(file, pressMachineFile(again.ptyPath(), plc.ptyPath(), feed.ptyPath())));
        const CliRun resumed = runCli({"machine", "backup", file, "-o", dir, "--resume"});
        VERIFY_EXIT(resumed, 0);
        QVERIFY2(resumed.out.contains(QLatin1String("== plc: kept from the earlier run")) &&
                     resumed.out.contains(QLatin1String("== feed: kept from the earlier run")) &&
                     resumed.out.contains(QLatin1String("3 of 3 devices saved")),
                 describe(resumed).constData());
        QVERIFY(camconRequests(again) > 0);
        const QJsonArray second = manifestDevices(dir);
        for (const char* kept : {"plc", "feed"})
            QCOMPARE(entryOf(second, kept), entryOf(first, kept));
        QCOMPARE(entryOf(second, "cams").value("result").toString(), QStringLiteral("saved"));
    }

    // Two names for one CamCon on one pty - its path and a link to it - and a
    // drive on another: the two on the one port are asked one after the
    // other (at once, the second open of the pty or the mixed requests
    // would fail one of them), the drive meanwhile; all three answer.
    void devicesSharingAPortAreAskedOneAfterTheOther() {
        SimSession cams;
        START_SIM(cams, {"--eprom", "03.05.2001"});
        SimSession feed(QStringLiteral("compax3"));
        START_SIM(feed, {"--drive-type", "S150V4"});
        const QString link = cams.path(QStringLiteral("ttyCams"));
        QVERIFY(QFile::link(cams.ptyPath(), link));
        const QJsonArray devices{deviceAt("cams", "camcon", cams.ptyPath()),
                                 deviceAt("feed", "compax3", feed.ptyPath()),
                                 deviceAt("cams-again", "camcon", link)};
        const QString file = cams.path(QStringLiteral("press7.json"));
        QVERIFY(writeBytes(
            file,
            QJsonDocument(QJsonObject{{"machine", "Press 7"}, {"devices", devices}}).toJson()));

        const CliRun status = runCli({"machine", "status", file});
        VERIFY_EXIT(status, 0);
        const QStringList lines = status.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 4);
        QVERIFY2(lines.at(1).startsWith(QStringLiteral("cams\tcamcon\t")) &&
                     lines.at(3).startsWith(QStringLiteral("cams-again\tcamcon\t") + link) &&
                     lines.at(3).contains(QLatin1String("03.05.2001")),
                 qPrintable(status.out));
    }
};

QTEST_GUILESS_MAIN(TestE2eMachineFamilies)
#include "tst_e2e_machine_families.moc"
