#pragma once

// A machine's archive (issue 37): its versions in a plain git repository,
// so that it can be pushed to the plant's server and read with any git
// tool. The work tree holds the latest version: a machine backup folder
// (machine.json, manifest.json, one readable file per device); each commit
// is a version whose author is the operator, whose committer is CamBench
// (fixed, so that it works where git was never configured) and whose
// message is the why and, under "Changed:", one line per changed device.
// A released version is marked by an annotated tag "released-N" (the
// highest N is the one that should be on the machine; the tagger is who
// released it). Runs the git program; knows nothing of devices or
// families - what changed is worked out by comm/usecases/machine_history.h.

#include "model/result.h"

#include <QByteArray>
#include <QDateTime>
#include <QList>
#include <QString>
#include <QStringList>

namespace cambench {

// A version of the archive (a commit).
struct ArchiveVersion {
    QString id;             // the full commit id
    QDateTime time;         // when it was stored (UTC)
    QString author;         // the operator
    QString note;           // why (-m); may be empty
    QStringList changes;    // one line per changed device: "cams: program 3: output 2, output 7"
    QStringList releases;   // the release tags on it ("released-2")
    bool released = false;  // it is the current release (the highest released-N)

    QString shortId() const { return id.left(10); }
};

// What a new version says of itself.
struct VersionMessage {
    QString author;  // the operator (--operator; the login name)
    QString note;    // why
    QStringList changes;
};

// The commit message of `message`: the note (or "machine backup" when
// none) as the subject, then "Changed:" and a line per change.
QString versionMessageText(const VersionMessage& message);
// The note and the changes of a commit message made by versionMessageText();
// another message is all note.
VersionMessage parseVersionMessage(const QString& text);

class MachineArchive {
public:
    // The archive at `dir`; a folder that is not the top of a git
    // repository is refused saying what to do.
    static Result<MachineArchive> open(const QString& dir);
    // The archive at `dir`, made (folder and repository) when missing.
    static Result<MachineArchive> openOrCreate(const QString& dir);

    const QString& dir() const { return m_dir; }

    // Every version, newest first (empty when none is stored yet).
    Result<QList<ArchiveVersion>> versions() const;
    // The commit id a person's name of a version stands for: a commit id
    // or a prefix of one, a tag, "released" (the current release), or
    // empty: the latest version.
    Result<QString> resolve(const QString& name) const;
    // The current release's commit id; an error saying so when no version
    // is released.
    Result<QString> released() const;
    // Marks version `id` as released by `operatorName` (a new tag
    // "released-N", N one more than the highest); the tag's name.
    Result<QString> release(const QString& id, const QString& operatorName,
                            const QString& note) const;

    // The files of version `id` (paths in the repository).
    Result<QStringList> files(const QString& id) const;
    // The version's files written into `folder` (made when missing).
    Status extract(const QString& id, const QString& folder) const;

    // Stores `files` of `folder` (paths relative to it) as a new version:
    // the work tree takes exactly those files (those of the last version
    // that are not among them go), then a commit. The new commit id.
    Result<QString> store(const QString& folder, const QStringList& files,
                          const VersionMessage& message) const;

    // The work tree's files as the latest version holds them (a backup into
    // the archive's folder that stored no version is undone).
    Status resetWorkTree() const;

private:
    explicit MachineArchive(QString dir) : m_dir(std::move(dir)) {}

    QString m_dir;
};

}  // namespace cambench
