// `cambench-cli diff` (issue 17, point 1): cam programs of two files, a file
// against the simulated device on a pseudo-terminal, the JSON, the exit
// codes, and the git diff driver on a repository of two commits.
#include "e2e_support.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTest>

#include <optional>

using namespace cambench::e2e;

namespace {

const QByteArray kHeader = "output,cam,on,off\n";

// git with `args` in `dir`: its stdout, or nothing when it failed.
std::optional<QString> git(const QString& dir, const QStringList& args) {
    QProcess process;
    process.setWorkingDirectory(dir);
    endWithThisTest(process);
    process.start(QStringLiteral("git"), args);
    if (!process.waitForFinished(hangBoundMs(60000)) || process.exitCode() != 0) {
        qWarning() << "git" << args << process.readAllStandardError();
        return std::nullopt;
    }
    return QString::fromUtf8(process.readAllStandardOutput());
}

// Moves the first cam of `output` in program 0 of a project file.
bool moveFirstCam(const QString& path, int output, int on, int off) {
    QJsonObject root = QJsonDocument::fromJson(readBytes(path)).object();
    QJsonArray programs = root.value(QStringLiteral("programs")).toArray();
    for (int p = 0; p < programs.size(); ++p) {
        QJsonObject program = programs.at(p).toObject();
        if (program.value(QStringLiteral("number")).toInt() != 0) continue;
        QJsonArray tracks = program.value(QStringLiteral("tracks")).toArray();
        for (int t = 0; t < tracks.size(); ++t) {
            QJsonObject track = tracks.at(t).toObject();
            if (track.value(QStringLiteral("output")).toInt() != output) continue;
            QJsonArray cams = track.value(QStringLiteral("cams")).toArray();
            cams[0] = QJsonArray{on, off};
            track.insert(QStringLiteral("cams"), cams);
            tracks[t] = track;
            program.insert(QStringLiteral("tracks"), tracks);
            programs[p] = program;
            root.insert(QStringLiteral("programs"), programs);
            return writeBytes(path, QJsonDocument(root).toJson());
        }
    }
    return false;
}

}  // namespace

class TestE2eDiff : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void twoCsvFiles() {
        QTemporaryDir dir;
        const QString a = dir.filePath(QStringLiteral("a.csv"));
        const QString b = dir.filePath(QStringLiteral("b.csv"));
        QVERIFY(writeBytes(a, kHeader + "1,1,10,90\n1,2,180,270\n3,1,5,9\n"));
        QVERIFY(writeBytes(b, kHeader + "1,1,12,90\n1,2,180,270\n4,1,100,120\n"));
        const CliRun run = runCli({"diff", a, b});
        VERIFY_EXIT(run, 1);
        QCOMPARE(run.out, QStringLiteral("output 1, cam 1: 10..90 → 12..90\n"
                                         "output 3: cam 5..9 only in A\n"
                                         "output 4: cam 100..120 only in B\n"));

        const CliRun json = runCli({"diff", a, b, "--json"});
        VERIFY_EXIT(json, 1);
        const QJsonObject root = QJsonDocument::fromJson(json.out.toUtf8()).object();
        QCOMPARE(root.value(QStringLiteral("equal")).toBool(true), false);
        const QJsonArray differences = root.value(QStringLiteral("differences")).toArray();
        QCOMPARE(differences.size(), 3);
        const QJsonObject changed = differences.at(0).toObject();
        QCOMPARE(changed.value(QStringLiteral("kind")).toString(), QStringLiteral("changed"));
        QCOMPARE(changed.value(QStringLiteral("output")).toInt(), 1);
        QCOMPARE(changed.value(QStringLiteral("b")).toObject().value(QStringLiteral("on")).toInt(),
                 12);

        const CliRun same = runCli({"diff", a, a});
        VERIFY_EXIT(same, 0);
        QVERIFY(same.out.isEmpty());
    }

    void badInputIsSaid() {
        QTemporaryDir dir;
        const QString a = dir.filePath(QStringLiteral("a.csv"));
        QVERIFY(writeBytes(a, kHeader + "1,1,10,90\n"));
        const CliRun missing = runCli({"diff", a, dir.filePath(QStringLiteral("gone.csv"))});
        VERIFY_EXIT(missing, 2);  // as every command given a file that is not there
        QVERIFY2(missing.err.contains(QLatin1String("gone.csv")), describe(missing));
        const CliRun device = runCli({"diff", a, "device"});
        VERIFY_EXIT(device, 2);
        QVERIFY2(device.err.contains(QLatin1String("--program")), describe(device));
        const CliRun one = runCli({"diff", a});
        VERIFY_EXIT(one, 2);
    }

    void fileAgainstTheDevice() {
        SimSession session;
        START_SIM(session);
        const QString read = session.path(QStringLiteral("read.csv"));
        VERIFY_EXIT(session.cli({"cams", "read", "--program", "0", "-o", read}), 0);
        const CliRun same = session.cli({"diff", read, "device", "--program", "0"});
        VERIFY_EXIT(same, 0);

        // Output 1's first cam moved in the file: the device still has the old one.
        QByteArray csv = readBytes(read);
        const QList<QByteArray> rows = csv.split('\n');
        QByteArray edited = rows.at(0) + '\n';
        QByteArray old;
        for (int i = 1; i < rows.size(); ++i) {
            if (rows.at(i).startsWith("1,1,") && old.isEmpty()) {
                old = rows.at(i);
                const QList<QByteArray> cells = old.split(',');
                edited += "1,1," + cells.at(2) + ',' + QByteArray::number(cells.at(3).toInt() + 5);
            } else {
                edited += rows.at(i);
            }
            if (i + 1 < rows.size()) edited += '\n';
        }
        QVERIFY2(!old.isEmpty(), csv.constData());
        QVERIFY(writeBytes(read, edited));
        const CliRun differs = session.cli({"diff", "device", read, "--program", "0"});
        VERIFY_EXIT(differs, 1);
        const QList<QByteArray> cells = old.split(',');
        QCOMPARE(differs.out,
                 QStringLiteral("output 1, cam 1: %1..%2 → %1..%3\n")
                     .arg(QString::fromLatin1(cells.at(2)), QString::fromLatin1(cells.at(3)))
                     .arg(cells.at(3).toInt() + 5));
    }

    void timingAtSpeedFromDeviceAndProject() {
        SimSession session;
        START_SIM(session);
        const CliRun run = session.cli({"timing", "--program", "0", "--speed", "60"});
        VERIFY_EXIT(run, 0);
        QVERIFY2(run.out.startsWith(
                     QLatin1String("program 0 at 60.0 1/min (360.0 pos/s), axis 0..359 rotary\n")),
                 describe(run));
        // The simulated device's output 1: dead time 2.5 ms, cams 10..90 and 180..270.
        QVERIFY2(run.out.contains(QLatin1String("output 1: shift 0.9 pos (dead time 2.5 ms), "
                                                "shortest cam 222.2 ms")),
                 describe(run));

        // The same numbers from a project file of the device, without it.
        const QString project = session.path(QStringLiteral("p.json"));
        VERIFY_EXIT(session.cli({"project", "read", "-o", project}), 0);
        const CliRun offline =
            runCli({"timing", "--project", project, "--program", "0", "--speed", "60"});
        VERIFY_EXIT(offline, 0);
        QCOMPARE(offline.out, run.out);

        // A minimum pulse the cams miss at speed: named, with the limit.
        const CliRun fast = runCli({"timing", "--project", project, "--program", "0", "--speed",
                                    "3000", "--min-pulse", "20", "--json"});
        VERIFY_EXIT(fast, 0);
        const QJsonObject root = QJsonDocument::fromJson(fast.out.toUtf8()).object();
        QCOMPARE(root.value(QStringLiteral("speedUnit")).toString(), QStringLiteral("1/min"));
        const QJsonObject first = root.value(QStringLiteral("outputs")).toArray().at(0).toObject();
        QCOMPARE(first.value(QStringLiteral("output")).toInt(), 1);
        QCOMPARE(first.value(QStringLiteral("limit")).toObject().value(QStringLiteral("kind")),
                 QJsonValue(QStringLiteral("shortPulse")));
        QVERIFY(!first.value(QStringLiteral("problems")).toArray().isEmpty());

        // Per output: output 1's own minimum pulse; a German decimal comma
        // is refused with the reason.
        const CliRun perOutput = runCli({"timing", "--project", project, "--program", "0",
                                         "--speed", "3000", "--min-pulse", "1=20", "--json"});
        VERIFY_EXIT(perOutput, 0);
        const QJsonArray timed =
            QJsonDocument::fromJson(perOutput.out.toUtf8()).object().value("outputs").toArray();
        QCOMPARE(timed.at(0).toObject().value(QStringLiteral("minPulseMs")).toDouble(), 20.0);
        for (int i = 1; i < timed.size(); ++i)
            QVERIFY(!timed.at(i).toObject().contains(QStringLiteral("minPulseMs")));
        const CliRun comma = runCli({"timing", "--project", project, "--program", "0", "--speed",
                                     "3000", "--min-pulse", "1=7,5"});
        VERIFY_EXIT(comma, 2);
        QVERIFY2(comma.err.contains(QStringLiteral("decimal point")), qPrintable(comma.err));

        const CliRun bad = runCli({"timing", "--program", "0", "--speed", "fast"});
        VERIFY_EXIT(bad, 2);
    }

    void gitDiffDriverForProjectFiles() {
        if (QStandardPaths::findExecutable(QStringLiteral("git")).isEmpty())
            QSKIP("git is not installed");
        SimSession session;
        START_SIM(session);
        QTemporaryDir repo;
        const QString project = repo.filePath(QStringLiteral("machine.json"));
        VERIFY_EXIT(session.cli({"project", "read", "-o", project}), 0);
        const QString dir = repo.path();
        QVERIFY(git(dir, {"init", "-q"}).has_value());
        QVERIFY(git(dir, {"config", "user.email", "test@example.com"}).has_value());
        QVERIFY(git(dir, {"config", "user.name", "Test"}).has_value());
        // What the README tells a user to set up.
        QVERIFY(
            writeBytes(repo.filePath(QStringLiteral(".gitattributes")), "*.json diff=cambench\n"));
        QVERIFY(git(dir, {"config", "diff.cambench.command",
                          QStringLiteral("'%1' diff --git").arg(QStringLiteral(CAMBENCH_CLI_EXE))})
                    .has_value());
        QVERIFY(git(dir, {"add", "."}).has_value());
        QVERIFY(git(dir, {"commit", "-q", "-m", "first"}).has_value());
        QVERIFY(moveFirstCam(project, 1, 11, 95));
        QVERIFY(git(dir, {"commit", "-q", "-a", "-m", "second"}).has_value());

        const QString diff = git(dir, {"diff", "HEAD~1", "HEAD"}).value_or(QString());
        QVERIFY2(diff.startsWith(QLatin1String("cambench diff machine.json\n")), qPrintable(diff));
        QVERIFY2(diff.contains(QLatin1String("program 0: output 1, cam 1: ")), qPrintable(diff));
        QVERIFY2(diff.contains(QStringLiteral(" → 11..95\n")), qPrintable(diff));
        // A new file: every program only in B.
        const QString added = git(dir, {"diff", "4b825dc642cb6eb9a060e54bf8d69288fbee4904", "HEAD"})
                                  .value_or(QString());
        QVERIFY2(added.contains(QLatin1String("program 0: only in B")), qPrintable(added));
    }

    // Issue 39, item 3: the driver is installed by the lines `diff
    // --git-setup` prints (with this cli's absolute path: git finds it
    // without PATH), and every CamBench file - an EEPROM image, settings, a
    // machine file, a CSV that is no cam file, a .json that is no JSON -
    // gets its differences shown, never "external diff died".
    void gitDiffDriverForEveryCamBenchFile() {
        if (QStandardPaths::findExecutable(QStringLiteral("git")).isEmpty())
            QSKIP("git is not installed");
        const CliRun setup = runCli({"diff", "--git-setup"});
        VERIFY_EXIT(setup, 0);
        QVERIFY2(setup.out.contains(
                     QStringLiteral("git config diff.cambench.command '%1 diff --git'")
                         .arg(QFileInfo(QStringLiteral(CAMBENCH_CLI_EXE)).absoluteFilePath())),
                 qPrintable(setup.out));
        SimSession session;
        START_SIM(session);
        QTemporaryDir repo;
        const QString dir = repo.path();
        VERIFY_EXIT(session.cli({"backup", "-o", repo.filePath("image.json")}), 0);
        VERIFY_EXIT(session.cli({"settings", "read", "-o", repo.filePath("settings.json")}), 0);
        VERIFY_EXIT(session.cli({"names", "read", "-o", repo.filePath("names.csv")}), 0);
        QVERIFY(writeBytes(repo.filePath("machine.json"),
                           "{\"machine\": \"Press 7\", \"devices\": [{\"name\": \"cams\", "
                           "\"family\": \"camcon\", \"port\": \"/dev/ttyUSB0\"}]}\n"));
        QVERIFY(writeBytes(repo.filePath("notes.json"), "first line\nnot JSON at all\n"));
        QVERIFY(git(dir, {"init", "-q"}).has_value());
        QVERIFY(git(dir, {"config", "user.email", "test@example.com"}).has_value());
        QVERIFY(git(dir, {"config", "user.name", "Test"}).has_value());
        // The printed lines, run as a person pastes them.
        QProcess shell;
        shell.setWorkingDirectory(dir);
        endWithThisTest(shell);
        shell.start(QStringLiteral("sh"), {QStringLiteral("-e"), QStringLiteral("-c"), setup.out});
        QVERIFY(shell.waitForFinished(hangBoundMs(30000)));
        QCOMPARE(shell.exitCode(), 0);
        QVERIFY(git(dir, {"add", "."}).has_value());
        QVERIFY(git(dir, {"commit", "-q", "-m", "first"}).has_value());

        // A changed member in each JSON file, a changed line in the others.
        for (const char* name : {"image.json", "settings.json"}) {
            QJsonObject root = QJsonDocument::fromJson(readBytes(repo.filePath(name))).object();
            QVERIFY2(!root.isEmpty(), name);
            root.insert(QStringLiteral("note"), QStringLiteral("changed"));
            QVERIFY(writeBytes(repo.filePath(name), QJsonDocument(root).toJson()));
        }
        QVERIFY(writeBytes(repo.filePath("machine.json"),
                           "{\"machine\": \"Press 7\", \"devices\": [{\"name\": \"cams\", "
                           "\"family\": \"camcon\", \"port\": \"/dev/ttyUSB1\"}]}\n"));
        QVERIFY(writeBytes(repo.filePath("notes.json"), "first line\nstill not JSON\n"));
        QByteArray names = readBytes(repo.filePath("names.csv"));
        QVERIFY(!names.isEmpty());
        QVERIFY(writeBytes(repo.filePath("names.csv"), names + "output,9,Glue valve\n"));
        QVERIFY(git(dir, {"commit", "-q", "-a", "-m", "second"}).has_value());

        // git's own PATH without the cli: the configured path alone finds it.
        const std::optional<QString> diff = git(dir, {"diff", "HEAD~1", "HEAD"});
        QVERIFY2(diff.has_value(), "git diff failed: the driver died");
        for (const char* expected :
             {"cambench diff image.json\n", "note: only in B: \"changed\"\n",
              "cambench diff settings.json\n", "cambench diff machine.json\n",
              "devices[0].port: \"/dev/ttyUSB0\" → \"/dev/ttyUSB1\"\n",
              "cambench diff notes.json\n", "-not JSON at all\n+still not JSON\n",
              "cambench diff names.csv\n", "+output,9,Glue valve\n"})
            QVERIFY2(diff->contains(QString::fromUtf8(expected)),
                     qPrintable(QStringLiteral("missing \"%1\" in:\n%2")
                                    .arg(QString::fromUtf8(expected), *diff)));
    }
};

QTEST_GUILESS_MAIN(TestE2eDiff)
#include "tst_e2e_diff.moc"
