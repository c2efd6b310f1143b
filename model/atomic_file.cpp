#include "atomic_file.h"

#include "model_log.h"

#include <QCoreApplication>
#include <QSaveFile>

namespace cambench {

namespace {

Error writeError(const QString& path, const QString& why) {
    return Error::usage(QCoreApplication::translate(
                            "cambench::model", "Could not write %1: %2. The file was not changed.")
                            .arg(path, why));
}

}  // namespace

Status writeFileAtomically(const QString& path, const QByteArray& bytes, FileAccess access) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) return writeError(path, file.errorString());
    // Set on the temporary file, which the commit renames into place: the
    // secrets are never readable by others, not even for a moment.
    if (access == FileAccess::OwnerOnly &&
        !file.setPermissions(QFileDevice::ReadOwner | QFileDevice::WriteOwner)) {
        const QString why = file.errorString();
        file.cancelWriting();
        return writeError(
            path, QCoreApplication::translate("cambench::model",
                                              "cannot make it readable by its owner only (%1)")
                      .arg(why));
    }
    if (file.write(bytes) != bytes.size()) {
        const QString why = file.errorString();
        file.cancelWriting();
        return writeError(path, why);
    }
    if (!file.commit()) return writeError(path, file.errorString());
    qCDebug(modelLog) << "wrote" << path << bytes.size() << "bytes";
    return success();
}

}  // namespace cambench
