// Issue 37: the machine archive - versions in a plain git repository made
// when missing, the operator as author and a fixed committer (no git
// configuration needed), the why and a line per changed device in the
// message, read back by `git log`; versions named by a commit id, a prefix
// or a tag; releases as tags "released-N"; a version taken out as it was
// stored; a device's file dropped from a version when it leaves. And the
// volatile items' matching.
#include "model/machine/machine_archive.h"
#include "model/machine/volatile_items.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using namespace cambench;

namespace {

void writeText(const QString& path, const QByteArray& text) {
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(text);
}

QByteArray readText(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// `git args` in `dir` as a person would run it, with no configuration of
// the user's (HOME elsewhere): what it printed.
QString git(const QString& dir, const QStringList& args) {
    QProcess process;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("HOME"), dir);
    env.insert(QStringLiteral("GIT_CONFIG_NOSYSTEM"), QStringLiteral("1"));
    process.setProcessEnvironment(env);
    process.start(QStringLiteral("git"), QStringList{QStringLiteral("-C"), dir} + args);
    process.waitForFinished();
    return QString::fromUtf8(process.readAllStandardOutput());
}

}  // namespace

class TestMachineArchive : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() {
        // No git configuration of the person running the test is used.
        qputenv("HOME", m_home.path().toUtf8());
    }

    void versionsStoredReadAndReleased() {
        QTemporaryDir work;
        const QString dir = work.filePath(QStringLiteral("press7-archive"));
        const QString stage = work.filePath(QStringLiteral("stage"));
        QDir().mkpath(stage);

        // Opening a folder that is none is refused saying how to make one.
        const Result<MachineArchive> none = MachineArchive::open(dir);
        QVERIFY(!none.ok());
        QVERIFY2(none.error().message.contains(QLatin1String("--archive")),
                 qPrintable(none.error().message));

        const Result<MachineArchive> archive = MachineArchive::openOrCreate(dir);
        QVERIFY2(archive.ok(), qPrintable(archive.error().message));
        QCOMPARE(archive->versions()->size(), 0);
        QVERIFY(!archive->resolve({}).ok());  // no version yet: said

        writeText(QDir(stage).filePath(QStringLiteral("cams.json")), "first cams\n");
        writeText(QDir(stage).filePath(QStringLiteral("feed.json")), "first feed\n");
        const Result<QString> first = archive->store(
            stage, {QStringLiteral("cams.json"), QStringLiteral("feed.json")},
            {QStringLiteral("alice"),
             QStringLiteral("commissioning"),
             {QStringLiteral("cams: first version"), QStringLiteral("feed: first version")}});
        QVERIFY2(first.ok(), qPrintable(first.error().message));

        // The second version lacks feed (taken out of the machine).
        writeText(QDir(stage).filePath(QStringLiteral("cams.json")), "second cams\n");
        const Result<QString> second =
            archive->store(stage, {QStringLiteral("cams.json")},
                           {QStringLiteral("bob"),
                            QStringLiteral("new glue pattern"),
                            {QStringLiteral("cams: program 3: output 2, output 7")}});
        QVERIFY2(second.ok(), qPrintable(second.error().message));
        QVERIFY(!QFile::exists(QDir(dir).filePath(QStringLiteral("feed.json"))));

        const Result<QList<ArchiveVersion>> versions = archive->versions();
        QVERIFY(versions.ok());
        QCOMPARE(versions->size(), 2);
        QCOMPARE(versions->at(0).id, *second);  // newest first
        QCOMPARE(versions->at(0).author, QStringLiteral("bob"));
        QCOMPARE(versions->at(0).note, QStringLiteral("new glue pattern"));
        QCOMPARE(versions->at(0).changes,
                 QStringList{QStringLiteral("cams: program 3: output 2, output 7")});
        QCOMPARE(versions->at(1).author, QStringLiteral("alice"));
        QVERIFY(qAbs(versions->at(1).time.secsTo(QDateTime::currentDateTimeUtc())) < 600);

        // Plain git reads it: author the operator, committer CamBench.
        QCOMPARE(git(dir, {"log", "--format=%an|%cn|%s"}),
                 QStringLiteral("bob|CamBench|new glue pattern\nalice|CamBench|commissioning\n"));
        QVERIFY(git(dir, {"show", "--stat", second->left(7)}).contains("cams.json"));

        // Names of a version: empty = latest, a prefix, the full id.
        QCOMPARE(*archive->resolve({}), *second);
        QCOMPARE(*archive->resolve(first->left(7)), *first);
        QVERIFY(!archive->resolve(QStringLiteral("0000000")).ok());
        QVERIFY(!archive->resolve(QStringLiteral("--all")).ok());
        QVERIFY(!archive->released().ok());  // none released yet: said

        QCOMPARE(*archive->release(*first, QStringLiteral("carol"), QStringLiteral("SAT")),
                 QStringLiteral("released-1"));
        QCOMPARE(*archive->released(), *first);
        QCOMPARE(*archive->resolve(QStringLiteral("released")), *first);
        QCOMPARE(*archive->resolve(QStringLiteral("released-1")), *first);
        QVERIFY(git(dir, {"tag", "-l", "--format=%(taggername)|%(contents:subject)"})
                    .contains(QLatin1String("carol|SAT")));
        QCOMPARE(*archive->release(*second, QStringLiteral("carol"), {}),
                 QStringLiteral("released-2"));
        const QList<ArchiveVersion> marked = *archive->versions();
        QVERIFY(marked.at(0).released);
        QVERIFY(!marked.at(1).released);
        QCOMPARE(marked.at(1).releases, QStringList{QStringLiteral("released-1")});

        // The first version taken out as it was stored.
        const QString out = work.filePath(QStringLiteral("out"));
        QVERIFY(archive->extract(*first, out).ok());
        QCOMPARE(readText(QDir(out).filePath(QStringLiteral("feed.json"))), "first feed\n");
        QCOMPARE(readText(QDir(out).filePath(QStringLiteral("cams.json"))), "first cams\n");
    }

    // A folder of files that is no repository is not made an archive.
    void folderWithFilesRefused() {
        QTemporaryDir work;
        writeText(work.filePath(QStringLiteral("notes.txt")), "mine\n");
        const Result<MachineArchive> archive = MachineArchive::openOrCreate(work.path());
        QVERIFY(!archive.ok());
        QVERIFY2(archive.error().message.contains(QLatin1String("no git repository")),
                 qPrintable(archive.error().message));
    }

    void messageWithoutChangesOrNote() {
        QCOMPARE(versionMessageText({QStringLiteral("a"), {}, {}}),
                 QStringLiteral("machine backup\n"));
        const VersionMessage parsed =
            parseVersionMessage(QStringLiteral("why\nand more\n\nChanged:\ncams: x\nfeed: y\n"));
        QCOMPARE(parsed.note, QStringLiteral("why\nand more"));
        QCOMPARE(parsed.changes, QStringList({"cams: x", "feed: y"}));
        QCOMPARE(parseVersionMessage(QStringLiteral("a commit made by hand\n")).note,
                 QStringLiteral("a commit made by hand"));
    }

    void volatileItems() {
        const QStringList items{QStringLiteral("V100-V199"), QStringLiteral("V12"),
                                QStringLiteral("1902.1-9"), QStringLiteral("M5-M6")};
        for (const char* key : {"V100", "V150", "V199", "V12", "1902.1", "1902.9", "M6"})
            QVERIFY2(isVolatileItem(items, QString::fromLatin1(key)), key);
        for (const char* key : {"V99", "V200", "V1", "V120a", "1902.10", "1903.1", "M7", "V"})
            QVERIFY2(!isVolatileItem(items, QString::fromLatin1(key)), key);
        QVERIFY(!checkVolatileItems({QStringLiteral("V9-V1")}, QStringLiteral("d")).ok());
        QVERIFY(checkVolatileItems(items, QStringLiteral("d")).ok());
    }

private:
    QTemporaryDir m_home;
};

QTEST_GUILESS_MAIN(TestMachineArchive)
#include "tst_machine_archive.moc"
