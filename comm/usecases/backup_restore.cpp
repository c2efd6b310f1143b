#include "backup_restore.h"

namespace cambench::usecases {

QString safetyBackupPath(const QString& imagePath, const QDateTime&) {
    return imagePath;
}
Result<EepromImage> backupDevice(comm::CamConDevice&, const UseCaseProgress&) {
    return Error::usage(QStringLiteral("not implemented yet"));
}
Result<EepromImage> backupToFile(comm::CamConDevice&, const QString&, const UseCaseProgress&) {
    return Error::usage(QStringLiteral("not implemented yet"));
}
RestoreReport restoreImage(comm::CamConDevice&, const EepromImage&, const QString&,
                           const RestoreOptions&, const UseCaseProgress&) {
    return {};
}
QString VerifyReport::text(const QString&) const {
    return {};
}
Result<VerifyReport> verifyImage(comm::CamConDevice&, const EepromImage&, const UseCaseProgress&) {
    return Error::usage(QStringLiteral("not implemented yet"));
}

}  // namespace cambench::usecases
