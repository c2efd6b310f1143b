// `cambench-cli short ...`: the S7-CP340 short commands 0x01..0x07 end to
// end against the real cambench-sim on the table interface (issue 12, point
// 5); every write is checked against the simulator's state through the other
// path (RK512 table reads), and refusals leave the device untouched.
#include "e2e_support.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace cambench::e2e;

namespace {

const QString kTable = QStringLiteral("3964r-n96");

QJsonObject jsonOf(const CliRun& run) {
    return QJsonDocument::fromJson(run.out.toUtf8()).object();
}

}  // namespace

class TestE2eShort : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void statusMatchesTheDevice();
    void programChangeIsConfirmedByTheStatus();
    void deadTimeWriteLandsAndReadsBack();
    void trackWriteLandsAndReadsBack();
    void refusalsSendNothing();
    void resetErrorsSaysWhatIsLeft();
    void otherProtocolsAreToldWhereShortCommandsTravel();
};

void TestE2eShort::statusMatchesTheDevice() {
    SimSession session(kTable);
    START_SIM(session);
    const CliRun run = session.cli({"short", "status", "--json"});
    VERIFY_EXIT(run, 0);
    const QJsonObject status = jsonOf(run);
    const CliRun other = session.cli({"status", "--json"});
    VERIFY_EXIT(other, 0);
    QCOMPARE(status.value("program").toInt(), jsonOf(other).value("program").toInt());
    QCOMPARE(status.value("deviceStatus").toInt(), 0);
    QVERIFY(status.value("outputCount").toInt() > 0);
    const CliRun text = session.cli({"short", "status"});
    VERIFY_EXIT(text, 0);
    QVERIFY2(text.out.contains(QLatin1String("deviceStatusText: ")), qPrintable(text.out));
}

void TestE2eShort::programChangeIsConfirmedByTheStatus() {
    SimSession session(kTable);
    START_SIM(session);
    const CliRun run = session.cli({"short", "program", "2"});
    VERIFY_EXIT(run, 0);
    // What the status query reports after the change, as the README says.
    QVERIFY2(run.out.contains(
                 QLatin1String("active program (0x03): written (the device reports program 2)")),
             qPrintable(run.out));
    QCOMPARE(jsonOf(session.cli({"status", "--json"})).value("program").toInt(), 2);
}

void TestE2eShort::deadTimeWriteLandsAndReadsBack() {
    SimSession session(kTable);
    START_SIM(session);
    const CliRun run = session.cli({"short", "deadtime", "write", "5", "125"});
    VERIFY_EXIT(run, 0);
    QVERIFY2(run.out.contains(QLatin1String("dead time of output 5 (0x07): written")),
             qPrintable(run.out));
    // The same value again is not sent.
    const CliRun again = session.cli({"short", "deadtime", "write", "5", "125"});
    VERIFY_EXIT(again, 0);
    QVERIFY2(again.out.contains(QLatin1String("unchanged")), qPrintable(again.out));
    const CliRun table = session.cli({"deadtimes", "read"});
    VERIFY_EXIT(table, 0);
    // The table interface prints the mode columns; the dead time is the mode normal's.
    QVERIFY2(table.out.contains(QLatin1String("\n5,125,normal,")), qPrintable(table.out));
    const CliRun back = session.cli({"short", "deadtime", "read", "5"});
    VERIFY_EXIT(back, 0);
    QCOMPARE(back.out, QStringLiteral("output,deadtime\n5,125\n"));
}

void TestE2eShort::trackWriteLandsAndReadsBack() {
    SimSession session(kTable);
    START_SIM(session);
    const QString file = session.path(QStringLiteral("track.csv"));
    const QByteArray cams = "output,cam,on,off\n5,1,10,20\n5,2,100,120\n";
    QVERIFY(writeBytes(file, cams));
    const CliRun run = session.cli({"short", "track", "write", "5", file, "--program", "1"});
    VERIFY_EXIT(run, 0);
    QVERIFY2(run.out.contains(QLatin1String("program 1, output 5 (0x05): written")),
             qPrintable(run.out));
    const CliRun table = session.cli({"cams", "read", "--program", "1", "--output", "5"});
    VERIFY_EXIT(table, 0);
    QCOMPARE(table.out.toUtf8(), cams);
    const CliRun back = session.cli({"short", "track", "read", "5", "--program", "1"});
    VERIFY_EXIT(back, 0);
    QCOMPARE(back.out.toUtf8(), cams);
}

void TestE2eShort::refusalsSendNothing() {
    SimSession session(kTable);
    START_SIM(session);
    const CliRun before = session.cli({"cams", "read", "--program", "0"});
    VERIFY_EXIT(before, 0);
    const QString file = session.path(QStringLiteral("track.csv"));
    QVERIFY(writeBytes(file, "output,cam,on,off\n5,1,10,20\n"));

    // No program: the cams would go into whatever runs.
    const CliRun noProgram = session.cli({"short", "track", "write", "5", file});
    VERIFY_EXIT(noProgram, 2);
    QVERIFY2(noProgram.err.contains(QLatin1String("--program")), qPrintable(noProgram.err));
    // A file with another output's cams.
    const CliRun otherOutput =
        session.cli({"short", "track", "write", "6", file, "--program", "0"});
    VERIFY_EXIT(otherOutput, 4);
    // More cams than the telegram holds.
    QByteArray many = "output,cam,on,off\n";
    for (int i = 0; i < 15; ++i)
        many += QByteArray("5,%1,%2,%3\n")
                    .replace("%1", QByteArray::number(i + 1))
                    .replace("%2", QByteArray::number(10 * i))
                    .replace("%3", QByteArray::number(10 * i + 5));
    QVERIFY(writeBytes(file, many));
    const CliRun tooMany = session.cli({"short", "track", "write", "5", file, "--program", "0"});
    QVERIFY2(tooMany.exitCode != 0, describe(tooMany).constData());
    // Outputs and programs the device does not have: data that does not fit
    // it (4); an output 0 is a command line that cannot be understood (2).
    VERIFY_EXIT(session.cli({"short", "program", "99"}), 4);
    VERIFY_EXIT(session.cli({"short", "deadtime", "read", "0"}), 2);
    VERIFY_EXIT(session.cli({"short", "deadtime", "write", "999", "5"}), 4);

    const CliRun after = session.cli({"cams", "read", "--program", "0"});
    VERIFY_EXIT(after, 0);
    QCOMPARE(after.out, before.out);
}

void TestE2eShort::resetErrorsSaysWhatIsLeft() {
    SimSession session(kTable);
    START_SIM(session);
    const CliRun run = session.cli({"short", "reset-errors"});
    VERIFY_EXIT(run, 0);
    QVERIFY2(run.out.contains(QLatin1String("error reset (0x02): written (device status now: ")),
             qPrintable(run.out));
}

void TestE2eShort::otherProtocolsAreToldWhereShortCommandsTravel() {
    SimSession session;
    START_SIM(session);
    const CliRun run = session.cli({"short", "status"});
    VERIFY_EXIT(run, 1);  // the protocol lacks them: the device's side (issue 39)
    QVERIFY2(run.err.contains(QLatin1String("exist only in")), qPrintable(run.err));
}

QTEST_GUILESS_MAIN(TestE2eShort)
#include "tst_e2e_short.moc"
