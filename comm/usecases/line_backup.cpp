#include "line_backup.h"

namespace cambench::usecases {

QString lineImageName(int, const DeviceInfo&) {
    return {};
}
Result<LineManifest> backupLine(comm::CamConDevice&, const LineBackupOptions&,
                                const UseCaseProgress&, const DeviceProgressFn&) {
    return Error::usage(QStringLiteral("not implemented yet"));
}
Result<QList<LineVerifyEntry>> verifyLine(comm::CamConDevice&, const QString&,
                                          const UseCaseProgress&, const DeviceProgressFn&) {
    return Error::usage(QStringLiteral("not implemented yet"));
}

}  // namespace cambench::usecases
