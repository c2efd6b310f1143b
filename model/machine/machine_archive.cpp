#include "machine_archive.h"

#include "model/atomic_file.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QProcessEnvironment>
#include <QRegularExpression>

#include <algorithm>

namespace cambench {

namespace {

const QString kReleasePrefix = QStringLiteral("released-");
const QString kChangedHeading = QStringLiteral("Changed:");
// The committer of every version and of nothing else: the operator is the
// author; a fixed committer lets git commit where no user.name is set.
const QString kCommitter = QStringLiteral("CamBench");
// A git that never answers (a lock held by a hung process) is said, not waited for.
constexpr int kGitTimeoutMs = 120000;

// What the git program printed, or why it failed: the command, its exit
// code and its own words.
struct GitRun {
    QByteArray out;
};

// Runs `git -C dir args...` with `who` as author and committer when
// given (else the fixed committer), no system or user configuration that
// could sign, hook into the pager or rename the first branch, and `input`
// on its standard input.
Result<GitRun> runGit(const QString& dir, const QStringList& args, const QString& who = {},
                      const QString& authorName = {}, const QByteArray& input = {}) {
    QProcess git;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("GIT_CONFIG_NOSYSTEM"), QStringLiteral("1"));
    env.insert(QStringLiteral("GIT_TERMINAL_PROMPT"), QStringLiteral("0"));
    env.insert(QStringLiteral("LC_ALL"), QStringLiteral("C"));
    env.insert(QStringLiteral("GIT_AUTHOR_NAME"), authorName.isEmpty() ? kCommitter : authorName);
    env.insert(QStringLiteral("GIT_AUTHOR_EMAIL"), QString());
    env.insert(QStringLiteral("GIT_COMMITTER_NAME"), who.isEmpty() ? kCommitter : who);
    env.insert(QStringLiteral("GIT_COMMITTER_EMAIL"), QString());
    git.setProcessEnvironment(env);
    git.setProgram(QStringLiteral("git"));
    git.setArguments(QStringList{QStringLiteral("-C"), dir, QStringLiteral("-c"),
                                 QStringLiteral("commit.gpgsign=false"), QStringLiteral("-c"),
                                 QStringLiteral("tag.gpgsign=false"), QStringLiteral("-c"),
                                 QStringLiteral("core.quotepath=false")} +
                     args);
    const QString command = QStringLiteral("git ") + args.join(QLatin1Char(' '));
    git.start();
    if (!git.waitForStarted())
        return Error::unsupported(
            QCoreApplication::translate(
                "cambench::model",
                "The git program could not be started (%1); the machine archive is a git "
                "repository: install git (Debian: apt install git).")
                .arg(git.errorString()));
    if (!input.isEmpty()) git.write(input);
    git.closeWriteChannel();
    if (!git.waitForFinished(kGitTimeoutMs)) {
        git.kill();
        git.waitForFinished();
        return Error::communication(
            QCoreApplication::translate(
                "cambench::model",
                "%1 in %2 did not finish within %3 s (a lock held by another git?); nothing "
                "more was done.")
                .arg(command, dir)
                .arg(kGitTimeoutMs / 1000));
    }
    if (git.exitStatus() != QProcess::NormalExit || git.exitCode() != 0)
        return Error::invalidData(
            QCoreApplication::translate("cambench::model", "%1 in %2 failed (exit %3): %4")
                .arg(command, dir)
                .arg(git.exitCode())
                .arg(QString::fromUtf8(git.readAllStandardError()).trimmed()));
    return GitRun{git.readAllStandardOutput()};
}

bool isRepositoryTop(const QString& dir) {
    const Result<GitRun> top =
        runGit(dir, {QStringLiteral("rev-parse"), QStringLiteral("--show-toplevel")});
    return top && QFileInfo(QString::fromUtf8(top->out).trimmed()).canonicalFilePath() ==
                      QFileInfo(dir).canonicalFilePath();
}

// Release tags with the commit each marks, highest number first.
struct ReleaseTag {
    QString name;
    int number = 0;
    QString commit;
};

Result<QList<ReleaseTag>> releaseTags(const QString& dir) {
    const Result<GitRun> listed =
        runGit(dir, {QStringLiteral("tag"), QStringLiteral("--list"), kReleasePrefix + u'*',
                     QStringLiteral("--format=%(refname:short) %(*objectname) %(objectname)")});
    if (!listed) return listed.error();
    QList<ReleaseTag> tags;
    for (const QString& line : QString::fromUtf8(listed->out).split(u'\n', Qt::SkipEmptyParts)) {
        const QStringList parts = line.split(u' ', Qt::SkipEmptyParts);
        bool ok = false;
        const int number = parts.value(0).mid(kReleasePrefix.size()).toInt(&ok);
        if (!ok || parts.size() < 2) continue;  // a tag a person named "released-x"
        // An annotated tag names its commit as *objectname; a light one has
        // none there, and its objectname is the commit.
        tags << ReleaseTag{parts.at(0), number, parts.at(1)};
    }
    std::sort(tags.begin(), tags.end(),
              [](const ReleaseTag& a, const ReleaseTag& b) { return a.number > b.number; });
    return tags;
}

}  // namespace

QString versionMessageText(const VersionMessage& message) {
    QString text = message.note.trimmed().isEmpty() ? QStringLiteral("machine backup")
                                                    : message.note.trimmed();
    if (!message.changes.isEmpty())
        text += QStringLiteral("\n\n") + kChangedHeading + u'\n' + message.changes.join(u'\n');
    return text + u'\n';
}

VersionMessage parseVersionMessage(const QString& text) {
    VersionMessage message;
    const QString marker = u'\n' + kChangedHeading + u'\n';
    const qsizetype at = text.lastIndexOf(marker);
    message.note = (at < 0 ? text : text.left(at)).trimmed();
    if (at >= 0)
        message.changes = text.mid(at + marker.size()).trimmed().split(u'\n', Qt::SkipEmptyParts);
    return message;
}

Result<MachineArchive> MachineArchive::open(const QString& dir) {
    if (!QFileInfo(dir).isDir())
        return Error::invalidData(
            QCoreApplication::translate(
                "cambench::model",
                "%1 is no machine archive: there is no such folder (`machine backup M.json "
                "--archive %1` makes one).")
                .arg(dir));
    if (!isRepositoryTop(dir))
        return Error::invalidData(
            QCoreApplication::translate("cambench::model",
                                        "%1 is no machine archive: it is not the top folder of a "
                                        "git repository (`machine backup M.json --archive DIR` "
                                        "makes one).")
                .arg(dir));
    return MachineArchive(QFileInfo(dir).absoluteFilePath());
}

Result<MachineArchive> MachineArchive::openOrCreate(const QString& dir) {
    if (QFileInfo(dir).isDir() && isRepositoryTop(dir)) return open(dir);
    if (!QDir().mkpath(dir))
        return Error::invalidData(
            QCoreApplication::translate(
                "cambench::model",
                "Cannot make the archive folder %1; check the path and its rights.")
                .arg(dir));
    if (!QDir(dir).isEmpty(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden))
        return Error::invalidData(
            QCoreApplication::translate("cambench::model",
                                        "%1 holds files but is no git repository: it is not made "
                                        "an archive (name an empty or new folder).")
                .arg(dir));
    if (const Result<GitRun> made = runGit(dir, {QStringLiteral("init"), QStringLiteral("--quiet"),
                                                 QStringLiteral("--initial-branch=main")});
        !made)
        return made.error();
    return open(dir);
}

Result<QList<ArchiveVersion>> MachineArchive::versions() const {
    // No commit yet: an archive just made.
    if (!runGit(m_dir, {QStringLiteral("rev-parse"), QStringLiteral("--verify"),
                        QStringLiteral("--quiet"), QStringLiteral("HEAD")}))
        return QList<ArchiveVersion>{};
    const Result<GitRun> log = runGit(
        m_dir, {QStringLiteral("log"), QStringLiteral("--format=%H%x1f%aN%x1f%aI%x1f%B%x1e")});
    if (!log) return log.error();
    const Result<QList<ReleaseTag>> tags = releaseTags(m_dir);
    if (!tags) return tags.error();
    QList<ArchiveVersion> versions;
    for (const QString& record : QString::fromUtf8(log->out).split(QChar(0x1e))) {
        const QStringList fields = record.trimmed().split(QChar(0x1f));
        if (fields.size() < 4) continue;
        ArchiveVersion version;
        version.id = fields.at(0);
        version.author = fields.at(1);
        version.time = QDateTime::fromString(fields.at(2), Qt::ISODate).toUTC();
        const VersionMessage message = parseVersionMessage(fields.at(3));
        version.note = message.note;
        version.changes = message.changes;
        for (const ReleaseTag& tag : *tags)
            if (tag.commit == version.id) version.releases << tag.name;
        version.released = !tags->isEmpty() && tags->first().commit == version.id;
        versions << version;
    }
    return versions;
}

Result<QString> MachineArchive::resolve(const QString& name) const {
    if (name == QLatin1String("released")) return released();
    const QString revision = name.isEmpty() ? QStringLiteral("HEAD") : name;
    // A name that starts with '-' would be an option to git.
    if (revision.startsWith(u'-'))
        return Error::usage(
            QCoreApplication::translate("cambench::model", "%1 names no version of %2.")
                .arg(name, m_dir));
    const Result<GitRun> found =
        runGit(m_dir, {QStringLiteral("rev-parse"), QStringLiteral("--verify"),
                       QStringLiteral("--quiet"), revision + QStringLiteral("^{commit}")});
    if (!found)
        return Error::usage(name.isEmpty()
                                ? QCoreApplication::translate(
                                      "cambench::model",
                                      "%1 holds no version yet (`machine backup M.json --archive "
                                      "%1 -m WHY` stores the first).")
                                      .arg(m_dir)
                                : QCoreApplication::translate(
                                      "cambench::model",
                                      "%1 names no version of %2 (`machine history %2` lists "
                                      "them: a commit id, a prefix of one or a tag).")
                                      .arg(name, m_dir));
    return QString::fromUtf8(found->out).trimmed();
}

Result<QString> MachineArchive::released() const {
    const Result<QList<ReleaseTag>> tags = releaseTags(m_dir);
    if (!tags) return tags.error();
    if (tags->isEmpty())
        return Error::usage(QCoreApplication::translate(
                                "cambench::model",
                                "No version of %1 is released (`machine release %1 VERSION` "
                                "marks the one that should be on the machine).")
                                .arg(m_dir));
    return tags->first().commit;
}

Result<QString> MachineArchive::release(const QString& id, const QString& operatorName,
                                        const QString& note) const {
    const Result<QList<ReleaseTag>> tags = releaseTags(m_dir);
    if (!tags) return tags.error();
    const QString name =
        kReleasePrefix + QString::number(tags->isEmpty() ? 1 : tags->first().number + 1);
    const QString message = note.trimmed().isEmpty() ? QStringLiteral("released") : note.trimmed();
    if (const Result<GitRun> tagged = runGit(m_dir,
                                             {QStringLiteral("tag"), QStringLiteral("--annotate"),
                                              QStringLiteral("--file=-"), name, id},
                                             operatorName, {}, message.toUtf8() + '\n');
        !tagged)
        return tagged.error();
    return name;
}

Result<QStringList> MachineArchive::files(const QString& id) const {
    const Result<GitRun> listed =
        runGit(m_dir, {QStringLiteral("ls-tree"), QStringLiteral("-r"),
                       QStringLiteral("--name-only"), QStringLiteral("-z"), id});
    if (!listed) return listed.error();
    return QString::fromUtf8(listed->out).split(QChar(0), Qt::SkipEmptyParts);
}

Status MachineArchive::extract(const QString& id, const QString& folder) const {
    const Result<QStringList> paths = files(id);
    if (!paths) return paths.error();
    for (const QString& path : *paths) {
        const Result<GitRun> blob =
            runGit(m_dir, {QStringLiteral("cat-file"), QStringLiteral("blob"), id + u':' + path});
        if (!blob) return blob.error();
        const QString target = QDir(folder).filePath(path);
        if (!QDir().mkpath(QFileInfo(target).absolutePath()))
            return Error::invalidData(
                QCoreApplication::translate("cambench::model", "Cannot make the folder for %1.")
                    .arg(target));
        // A CamCon image holds access codes: no file of a version is
        // readable by others than its owner once taken out of the archive.
        if (const Status written = writeFileAtomically(target, blob->out, FileAccess::OwnerOnly);
            !written)
            return written;
    }
    return success();
}

Status MachineArchive::resetWorkTree() const {
    const Result<GitRun> reset =
        runGit(m_dir, {QStringLiteral("checkout"), QStringLiteral("--force"),
                       QStringLiteral("HEAD"), QStringLiteral("--"), QStringLiteral(".")});
    if (!reset) return reset.error();
    return success();
}

Result<QString> MachineArchive::store(const QString& folder, const QStringList& files,
                                      const VersionMessage& message) const {
    // The last version's files that the new one lacks (a device taken out).
    const Result<GitRun> tracked =
        runGit(m_dir, {QStringLiteral("ls-files"), QStringLiteral("-z")});
    if (!tracked) return tracked.error();
    for (const QString& path : QString::fromUtf8(tracked->out).split(QChar(0), Qt::SkipEmptyParts))
        if (!files.contains(path))
            if (const Result<GitRun> removed = runGit(
                    m_dir,
                    {QStringLiteral("rm"), QStringLiteral("--quiet"), QStringLiteral("--"), path});
                !removed)
                return removed.error();
    for (const QString& path : files) {
        const QString source = QDir(folder).filePath(path);
        const QString target = QDir(m_dir).filePath(path);
        QFile file(source);
        if (!file.open(QIODevice::ReadOnly))
            return Error::invalidData(
                QCoreApplication::translate("cambench::model",
                                            "Cannot read %1: %2; no version was stored.")
                    .arg(source, file.errorString()));
        const QFileDevice::Permissions mode = file.permissions();
        if (const Status written = writeFileAtomically(
                target, file.readAll(),
                mode & QFileDevice::ReadOther ? FileAccess::Default : FileAccess::OwnerOnly);
            !written)
            return written.error();
    }
    if (const Result<GitRun> added =
            runGit(m_dir, QStringList{QStringLiteral("add"), QStringLiteral("--")} + files);
        !added)
        return added.error();
    if (const Result<GitRun> committed = runGit(
            m_dir,
            {QStringLiteral("commit"), QStringLiteral("--quiet"), QStringLiteral("--file=-")}, {},
            message.author, versionMessageText(message).toUtf8());
        !committed)
        return committed.error();
    return resolve({});
}

}  // namespace cambench
