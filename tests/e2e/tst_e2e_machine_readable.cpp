// Issue 36, items 1-3: a machine of three simulators on ptys - a CamCon, an
// MC200 and a Compax3 - backed up by `machine backup` through each
// family's typed backup part; then one change on each device behind
// CamBench's back. `machine diff` of the two backups and `machine verify`
// of the first name each change in its family's terms; the files read one
// item a line; the manifest says who took the backup, why and with what;
// the restore's safety copy lies beside the backup folder (never inside),
// listed in a manifest of its own, with the mode of the file it copies.
#include "e2e_support.h"
#include "press_machine.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace cambench::e2e;

namespace {

QJsonObject manifestOf(const QString& dir) {
    return QJsonDocument::fromJson(readBytes(dir + QStringLiteral("/manifest.json"))).object();
}

// The three changes, each in its family's words.
const QStringList kChanges{
    QStringLiteral("cams: program 0, output 5: cam 100–200 added"),
    QStringLiteral("plc: V12 0 → 4711"),
    QStringLiteral("feed: 1902.1 Set 1 velocity 200 → 321"),
};

bool namesEachChange(const QString& out) {
    for (const QString& change : kChanges)
        if (!out.contains(change + QLatin1Char('\n'))) return false;
    return true;
}

}  // namespace

class TestE2eMachineReadable : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void changesAreNamedInEachFamilysTerms() {
        SimSession cams;
        SimSession plc(QStringLiteral("mc1"));
        SimSession feed(QStringLiteral("compax3"));
        startPress(cams, plc, feed, {"--outputs", "16"});
        if (QTest::currentTestFailed()) return;
        const QString file = cams.path(QStringLiteral("press7.json"));
        QVERIFY(writeBytes(file, pressMachineFile(cams.ptyPath(), plc.ptyPath(), feed.ptyPath())));
        const QString first = cams.path(QStringLiteral("first"));
        const QString second = cams.path(QStringLiteral("second"));

        const CliRun backup = runCli({"machine", "backup", file, "-o", first, "--operator",
                                      "Anna Berg", "-m", "after commissioning"});
        VERIFY_EXIT(backup, 0);
        QVERIFY2(backup.out.contains(QLatin1String("3 of 3 devices saved")) &&
                     backup.out.contains(QLatin1String("by Anna Berg: \"after commissioning\"")),
                 describe(backup).constData());
        const QJsonObject manifest = manifestOf(first);
        QCOMPARE(manifest.value("operator").toString(), QStringLiteral("Anna Berg"));
        QCOMPARE(manifest.value("note").toString(), QStringLiteral("after commissioning"));
        QVERIFY2(!manifest.value("tool").toString().isEmpty() &&
                     !manifest.value("revision").toString().isEmpty(),
                 readBytes(first + "/manifest.json").constData());
        for (const QJsonValue& entry : manifest.value("devices").toArray())
            QVERIFY2(!entry.toObject().value("summary").toString().isEmpty(),
                     readBytes(first + "/manifest.json").constData());
        VERIFY_EXIT(runCli({"machine", "verify", first}), 0);
        VERIFY_EXIT(runCli({"machine", "diff", first, first}), 0);

        // One change on each device behind CamBench's back.
        const QString csv = cams.path(QStringLiteral("output5.csv"));
        QVERIFY(writeBytes(csv, "output,cam,on,off\n5,1,100,200\n"));
        VERIFY_EXIT(cams.cli({"cams", "write", "--program", "0", csv}), 0);
        VERIFY_EXIT(plc.cli({"mc", "var", "write", "12", "4711"}), 0);
        VERIFY_EXIT(feed.cli({"c3", "write", "1902.1=321"}), 0);

        // Without --operator: the login name.
        VERIFY_EXIT(runCli({"machine", "backup", file, "-o", second, "-m", "new knife"}), 0);
        const QString who = manifestOf(second).value("operator").toString();
        QVERIFY(!who.isEmpty() && who != QLatin1String("Anna Berg"));

        const CliRun diff = runCli({"machine", "diff", first, second});
        VERIFY_EXIT(diff, 1);
        QVERIFY2(namesEachChange(diff.out), qPrintable(diff.out));
        QVERIFY2(diff.out.contains(QLatin1String("cams: DIFFERS (1)\nplc: DIFFERS (1)\n"
                                                 "feed: DIFFERS (1)")),
                 qPrintable(diff.out));
        const CliRun verify = runCli({"machine", "verify", first});
        VERIFY_EXIT(verify, 1);
        QVERIFY2(namesEachChange(verify.out), qPrintable(verify.out));

        // The files a person reads, one item a line: a git diff of the two
        // backups shows the very lines.
        QVERIFY(readBytes(second + "/cams.json").contains("{\"cams\":[[100,200]],\"output\":5}"));
        QVERIFY(readBytes(second + "/plc.json").contains("[12,4711]"));
        QVERIFY(readBytes(second + "/plc.json").contains("[\"M1\",1]"));
        QVERIFY(
            readBytes(second + "/feed.json").contains("[\"1902.1\",\"321\",\"Set 1 velocity\"]"));

        // The plan names what will be written and writes nothing.
        const CliRun plan = runCli({"machine", "restore", first, "--plan"});
        VERIFY_EXIT(plan, 0);
        QVERIFY2(plan.out.contains(QStringLiteral("will write: plc: V12 4711 → 0")) &&
                     plan.out.contains(QStringLiteral(
                         "will write: cams: program 0, output 5: cam 100–200 removed")),
                 qPrintable(plan.out));
        VERIFY_EXIT(runCli({"machine", "verify", first}), 1);
        const QStringList inside = QDir(first).entryList(QDir::Files, QDir::Name);

        const CliRun restore = runCli({"machine", "restore", first, "-m", "back to commissioning"});
        VERIFY_EXIT(restore, 0);
        QCOMPARE(QDir(first).entryList(QDir::Files, QDir::Name), inside);  // nothing added inside
        const QStringList beside =
            QDir(cams.path(QString())).entryList({QStringLiteral("first.safety-*")}, QDir::Dirs);
        QCOMPARE(beside.size(), 1);
        const QString safety = cams.path(beside.first());
        QVERIFY2(restore.out.contains(safety + QStringLiteral("/cams.json")),
                 qPrintable(restore.out));
        const QJsonObject listed = manifestOf(safety);
        QCOMPARE(listed.value("safetyCopyOf").toString(), QFileInfo(first).absoluteFilePath());
        QCOMPARE(listed.value("note").toString(), QStringLiteral("back to commissioning"));
        QCOMPARE(listed.value("devices").toArray().size(), 1);
        QCOMPARE(listed.value("devices").toArray().at(0).toObject().value("name").toString(),
                 QStringLiteral("cams"));
        QCOMPARE(QFile::permissions(safety + "/cams.json"),
                 QFile::permissions(first + "/cams.json"));
        QCOMPARE(QFile::permissions(safety + "/manifest.json"),
                 QFile::permissions(first + "/manifest.json"));
        VERIFY_EXIT(runCli({"machine", "verify", first}), 0);
        // The safety copy holds the changed CamCon, its blocks alone (taken
        // just before the erase): it differs, named by its blocks.
        const CliRun back = runCli({"machine", "verify", safety});
        VERIFY_EXIT(back, 1);
        QVERIFY2(back.out.contains(QLatin1String("cams: EEPROM: blocks")) &&
                     back.out.contains(QLatin1String("Press 7:\ncams: DIFFERS (1)\n")),
                 qPrintable(back.out));
    }
};

QTEST_GUILESS_MAIN(TestE2eMachineReadable)
#include "tst_e2e_machine_readable.moc"
