#include "file_read.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

namespace cambench {

Result<QByteArray> readFileBytes(const QString& path, qint64 maxBytes) {
    const QFileInfo info(path);
    if (!info.exists())
        return Error::usage(QCoreApplication::translate(
                                "cambench::model", "Could not read %1: the file does not exist.")
                                .arg(path));
    if (!info.isFile())
        return Error::usage(QCoreApplication::translate(
                                "cambench::model", "Could not read %1: it is not a regular file.")
                                .arg(path));
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return Error::usage(QCoreApplication::translate("cambench::model", "Could not read %1: %2.")
                                .arg(path, file.errorString()));
    QByteArray bytes = file.read(maxBytes + 1);
    if (bytes.size() > maxBytes) {
        return Error::invalidData(
            QCoreApplication::translate(
                "cambench::model",
                "Could not read %1: it is larger than %2 bytes, so it is not a "
                "CamBench file.")
                .arg(path)
                .arg(maxBytes));
    }
    if (file.error() != QFileDevice::NoError)
        return Error::usage(QCoreApplication::translate("cambench::model", "Could not read %1: %2.")
                                .arg(path, file.errorString()));
    return bytes;
}

Error inFile(const QString& path, const Error& error) {
    Error located = error;
    located.message = QStringLiteral("%1: %2").arg(path, error.message);
    return located;
}

}  // namespace cambench
