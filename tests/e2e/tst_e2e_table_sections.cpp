// Issue 12, point 2: the dead-time modes, which only the table interface
// reaches, go through the one write path: a project read from one simulated
// device carries them to another, `deadtimes read` prints the mode columns
// and `deadtimes write` writes them, each reported per item; over a protocol
// without them they are reported as not sent, never as written.
#include "e2e_support.h"

#include "model/camcon/project_file.h"

#include <QTest>

using namespace cambench;
using namespace cambench::e2e;

namespace {

const QString kTable = QStringLiteral("3964r-n96");

}  // namespace

class TestE2eTableSections : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void projectCarriesDeadTimeModesToAnotherDevice();
    void deadTimesCsvWithModesRoundTrips();
    void modesOverAsciiAreNotSent();
};

void TestE2eTableSections::projectCarriesDeadTimeModesToAnotherDevice() {
    SimSession source(kTable);
    START_SIM(source);
    const QString file = source.path(QStringLiteral("project.json"));
    VERIFY_EXIT(source.cli({"project", "read", "-o", file}), 0);
    const Result<Project> loaded = loadProject(file);
    QVERIFY2(loaded.ok(), qPrintable(loaded.error().message));
    Project project = *loaded;
    QCOMPARE(project.deadTimeModes.size(), 32);
    QCOMPARE(project.deadTimeModes.value(2).mode, DeadTimeMode::SeparateOnOff);
    // Output 5 edited on the PC: separate switch-on and switch-off dead times.
    project.deadTimeModes.insert(5, OutputDeadTime{DeadTimeMode::SeparateOnOff, 0, 35, 47});
    project.deadTimes.insert(5, 0);
    QVERIFY(saveProject(file, project).ok());

    SimSession target(kTable);
    START_SIM(target, {"--fill", "1"});
    const CliRun written = target.cli({"project", "write", file});
    VERIFY_EXIT(written, 0);
    QVERIFY2(written.out.contains(QLatin1String("dead-time mode of output 5: written")),
             qPrintable(written.out));
    QVERIFY2(written.out.contains(QLatin1String("dead-time mode of output 2: unchanged")),
             qPrintable(written.out));
    const CliRun read = target.cli({"deadtimes", "read"});
    VERIFY_EXIT(read, 0);
    QVERIFY2(read.out.startsWith(QLatin1String("output,deadtime,mode,on,off\n")),
             qPrintable(read.out));
    QVERIFY2(read.out.contains(QLatin1String("\n5,0,on/off,35,47\n")), qPrintable(read.out));
}

void TestE2eTableSections::deadTimesCsvWithModesRoundTrips() {
    SimSession session(kTable);
    START_SIM(session);
    const QString file = session.path(QStringLiteral("modes.csv"));
    QVERIFY(
        writeBytes(file, "output,deadtime,mode,on,off\n7,0,path-time,20,300\n8,55,normal,0,0\n"));
    const CliRun written = session.cli({"deadtimes", "write", file});
    VERIFY_EXIT(written, 0);
    QVERIFY2(written.out.contains(QLatin1String("dead-time mode of output 7: written")),
             qPrintable(written.out));
    const CliRun read = session.cli({"deadtimes", "read"});
    QVERIFY2(read.out.contains(QLatin1String("\n7,0,path-time,20,300\n")), qPrintable(read.out));
    QVERIFY2(read.out.contains(QLatin1String("\n8,55,normal,0,0\n")), qPrintable(read.out));
    // A mode the device does not know: refused before anything is sent.
    QVERIFY(writeBytes(file, "output,deadtime,mode,on,off\n7,0,sideways,20,300\n"));
    VERIFY_EXIT(session.cli({"deadtimes", "write", file}), 4);
}

void TestE2eTableSections::modesOverAsciiAreNotSent() {
    SimSession session;  // Standard: no dead-time modes
    START_SIM(session);
    const QString file = session.path(QStringLiteral("modes.csv"));
    QVERIFY(writeBytes(file, "output,deadtime,mode,on,off\n7,0,path-time,20,300\n"));
    const CliRun written = session.cli({"deadtimes", "write", file});
    QVERIFY2(written.exitCode != 0, describe(written).constData());
    QVERIFY2(written.out.contains(QLatin1String("dead-time mode of output 7: not sent")),
             describe(written).constData());
    QVERIFY2(!written.out.contains(QLatin1String(": written")), qPrintable(written.out));
}

QTEST_GUILESS_MAIN(TestE2eTableSections)
#include "tst_e2e_table_sections.moc"
