// A noisy line and a dead device, with the real executables.
#include "e2e_support.h"

#include <QFile>
#include <QTest>

using namespace cambench::e2e;

class TestE2eFaults : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void corruptRepliesStillGiveCorrectResults();
    void deadDeviceExitsThreeWithOneClearLine_data();
    void deadDeviceExitsThreeWithOneClearLine();
    void missingPortExitsThree();
};

void TestE2eFaults::corruptRepliesStillGiveCorrectResults() {
    SimSession clean;
    START_SIM(clean);
    const CliRun cleanCams = clean.cli({"cams", "read", "--program", "0"});
    VERIFY_EXIT(cleanCams, 0);
    const CliRun cleanInfo = clean.cli({"info"});
    VERIFY_EXIT(cleanInfo, 0);

    SimSession noisy;
    START_SIM(noisy, {"--corrupt", "0.01", "--seed", "7"});
    const CliRun info = noisy.cli({"info"});
    VERIFY_EXIT(info, 0);
    // Free RAM and cam counts are the same on two fresh devices.
    QCOMPARE(info.out, cleanInfo.out);
    const CliRun cams = noisy.cli({"cams", "read", "--program", "0"});
    VERIFY_EXIT(cams, 0);
    QCOMPARE(cams.out, cleanCams.out);

    const QString csv = noisy.path(QStringLiteral("cams.csv"));
    QVERIFY(writeBytes(csv, "output,cam,on,off\n7,1,11,22\n7,2,33,44\n"));
    VERIFY_EXIT(noisy.cli({"cams", "write", "--program", "1", csv}), 0);
    const CliRun track = noisy.cli({"cams", "read", "--program", "1", "--output", "7"});
    QCOMPARE(track.out, QStringLiteral("output,cam,on,off\n7,1,11,22\n7,2,33,44\n"));

    const QString image = noisy.path(QStringLiteral("image.json"));
    VERIFY_EXIT(noisy.cli({"backup", "-o", image}), 0);
    const QString log = noisy.path(QStringLiteral("restore.log"));
    const CliRun restore = noisy.cli({"--log", log, "restore", "--no-safety-backup", image});
    QVERIFY2(restore.exitCode == 0, describe(restore) + readBytes(log));
    VERIFY_EXIT(noisy.cli({"verify", image}), 0);
}

void TestE2eFaults::deadDeviceExitsThreeWithOneClearLine_data() {
    QTest::addColumn<QStringList>("simArgs");
    QTest::newRow("dead") << QStringList{QStringLiteral("--dead")};
    QTest::newRow("drop all") << QStringList{QStringLiteral("--drop"), QStringLiteral("1")};
}

void TestE2eFaults::deadDeviceExitsThreeWithOneClearLine() {
    QFETCH(QStringList, simArgs);
    SimSession session;
    START_SIM(session, simArgs);
    for (const QStringList& command :
         {QStringList{"info"}, QStringList{"cams", "read", "--program", "0"},
          QStringList{"backup", "-o", session.path(QStringLiteral("x.json"))}}) {
        // The bound only catches a hang: 4 attempts of 200 ms are expected.
        const CliRun run = session.cli(QStringList{"--timeout", "200"} + command, 30000);
        QVERIFY2(run.finished, describe(run).constData());
        VERIFY_EXIT(run, 3);
        QVERIFY(run.out.isEmpty());
        QVERIFY2(run.err.startsWith(QLatin1String("cambench-cli: ")), qPrintable(run.err));
        QCOMPARE(run.err.count(u'\n'), 1);
        QVERIFY2(run.err.contains(QLatin1String("check")), qPrintable(run.err));
    }
    QVERIFY(!QFile::exists(session.path(QStringLiteral("x.json"))));
}

void TestE2eFaults::missingPortExitsThree() {
    const CliRun run = runCli({"--port", "/dev/does-not-exist-cambench", "info"}, 30000);
    VERIFY_EXIT(run, 3);
    QVERIFY(run.err.startsWith(QLatin1String("cambench-cli: ")));
}

QTEST_GUILESS_MAIN(TestE2eFaults)
#include "tst_e2e_faults.moc"
