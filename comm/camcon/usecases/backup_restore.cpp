#include "backup_restore.h"

#include "read_everything.h"

#include "model/camcon/eeprom_image_file.h"
#include "model/camcon/link_settings.h"
#include "model/camcon/project_content.h"

#include <QCoreApplication>
#include <QFileInfo>

namespace cambench::usecases {

namespace {

using comm::CamConCapability;
using comm::CamConDevice;

// Blocks listed when an image and a device differ: enough to see where.
constexpr int kListedBlocks = 10;

QString hex4(int number) {
    return QStringLiteral("%1").arg(number, 4, 16, QLatin1Char('0')).toUpper();
}

}  // namespace

QStringList differingEepromBlocks(const QList<EepromBlock>& device,
                                  const QList<EepromBlock>& image) {
    QStringList differences;
    const int count = int(qMax(device.size(), image.size()));
    for (int i = 0; i < count && differences.size() < kListedBlocks; ++i) {
        if (i < device.size() && i < image.size() && device.at(i) == image.at(i)) continue;
        differences << hex4(i < image.size() ? image.at(i).number : device.at(i).number);
    }
    return differences;
}

namespace {

Error withMessage(Error error, const QString& message) {
    error.message = message;
    return error;
}

SystemSettings linkOf(const DeviceInfo& device) {
    return {{QStringLiteral("deviceNumber"), qint64(device.deviceNumber)},
            {QStringLiteral("protocol"), qint64(device.protocol)}};
}

// Issue 39: an image is a byte image of the device it was taken from, its
// communication settings included (the blocks are opaque: nothing can be
// left out of them). A restore puts the device back as it was, those
// settings too; when the device uses others now, the person must know that
// the next connection needs the image's.
QString linkNote(const DeviceInfo& image, const DeviceInfo& now) {
    if (image.protocol == now.protocol && image.deviceNumber == now.deviceNumber) return {};
    return QCoreApplication::translate(
               "cambench::usecases",
               "The image holds the communication settings the device had when it was taken, "
               "%1 (it uses %2 now). A restore puts them back with everything else: the next "
               "connection to the device needs %1.")
        .arg(linkSettingsText(linkOf(image)), linkSettingsText(linkOf(now)));
}

}  // namespace

QString safetyBackupPath(const QString& imagePath, const QDateTime& utc) {
    const QString stem =
        QStringLiteral("%1.safety-%2")
            .arg(imagePath, utc.toUTC().toString(QStringLiteral("yyyyMMdd'T'HHmmss'Z'")));
    QString path = stem + QStringLiteral(".json");
    for (int n = 2; QFileInfo::exists(path); ++n)
        path = QStringLiteral("%1-%2.json").arg(stem).arg(n);
    return path;
}

Result<EepromImage> backupDevice(CamConDevice& connection, const UseCaseProgress& progress) {
    if (!connection.has(CamConCapability::EepromBackup))
        return connection.missing(CamConCapability::EepromBackup);
    return connection.backup(progress.forDevice(
        QCoreApplication::translate("cambench::usecases", "reading the EEPROM")));
}

Result<EepromImage> backupToFile(CamConDevice& connection, const QString& path,
                                 const UseCaseProgress& progress, BackupContent content) {
    const bool decoded = content == BackupContent::Decoded;
    const Result<EepromImage> blocks =
        backupDevice(connection, decoded ? progress.slice(0, 1, 2) : progress);
    if (!blocks) return blocks.error();
    EepromImage image = *blocks;
    if (decoded) {
        const Result<ReadEverything> read =
            readEverything(connection, image.device, progress.slice(1, 1, 2));
        if (!read) return read.error();
        image.content = projectContentJson(read->project);
    }
    const Status saved = saveEepromImage(path, image);
    if (!saved) return saved.error();
    return image;
}

RestoreReport restoreImage(CamConDevice& connection, const EepromImage& image,
                           const QString& imagePath, const RestoreOptions& options,
                           const UseCaseProgress& progress) {
    RestoreReport report;
    report.blocks = int(image.blocks.size());
    if (!connection.has(CamConCapability::EepromBackup)) {
        report.error = connection.missing(CamConCapability::EepromBackup);
        return report;
    }
    const Result<DeviceInfo> device = connection.readInfo();
    if (!device) {
        report.error = withMessage(
            device.error(),
            QCoreApplication::translate("cambench::usecases", "%1 The device was not changed.")
                .arg(device.error().message));
        return report;
    }
    if (const Status target = checkRestoreTarget(
            camConIdentity(image.device), camConIdentity(*device), options.replacement, imagePath);
        !target) {
        report.error = target.error();
        return report;
    }
    report.identityMismatch = identityMismatch(image.device, *device);

    report.linkNote = linkNote(image.device, *device);
    const qint64 steps = options.safetyBackup ? 2 : 1;
    if (options.safetyBackup) {
        const QString path = options.safetyBackupPath.isEmpty()
                                 ? safetyBackupPath(imagePath, QDateTime::currentDateTimeUtc())
                                 : options.safetyBackupPath;
        const UseCaseProgress part = progress.slice(0, 1, steps);
        const Result<EepromImage> safety = backupToFile(
            connection, path,
            UseCaseProgress(
                [part](qint64 done, qint64 total, const QString&) {
                    part.report(done, total,
                                QCoreApplication::translate("cambench::usecases",
                                                            "step 1 of 2: safety backup"));
                },
                [progress] { return progress.cancelled(); }),
            BackupContent::ImageOnly);
        if (!safety) {
            report.error = withMessage(
                safety.error(),
                QCoreApplication::translate("cambench::usecases",
                                            "Cannot take the safety backup before the restore: "
                                            "%1 The device was not changed.")
                    .arg(safety.error().message));
            return report;
        }
        report.safetyBackupPath = path;
    }
    if (progress.cancelled()) {
        report.error = withMessage(
            Error::cancelled(),
            QCoreApplication::translate("cambench::usecases",
                                        "Cancelled before the restore started. The device "
                                        "was not changed."));
        return report;
    }
    const UseCaseProgress part = progress.slice(steps - 1, 1, steps);
    const QString text =
        options.safetyBackup
            ? QCoreApplication::translate("cambench::usecases", "step 2 of 2: restore")
            : QCoreApplication::translate("cambench::usecases", "restore");
    const Status restored = connection.restore(image, part.forDevice(text));
    if (restored) {
        report.state = RestoredState::Restored;
        return report;
    }
    // The device layer checks the image before sending: InvalidData means
    // nothing was sent.
    report.state = restored.error().kind == ErrorKind::InvalidData ? RestoredState::Unchanged
                                                                   : RestoredState::ErasedOrPartial;
    QString message = restored.error().message;
    if (report.state == RestoredState::ErasedOrPartial) {
        message +=
            report.safetyBackupPath.isEmpty()
                ? QCoreApplication::translate("cambench::usecases", " No safety backup was taken.")
                : QCoreApplication::translate(
                      "cambench::usecases",
                      " The device's previous content is in the safety backup %1.")
                      .arg(report.safetyBackupPath);
    }
    report.error = withMessage(restored.error(), message);
    return report;
}

QString VerifyReport::text(const QString& imagePath) const {
    if (equal)
        return QCoreApplication::translate("cambench::usecases", "the device equals %1 (%2 blocks)")
            .arg(imagePath)
            .arg(imageBlocks);
    QString text =
        QCoreApplication::translate("cambench::usecases",
                                    "the device differs from %1: device %2 blocks, image %3 blocks")
            .arg(imagePath)
            .arg(deviceBlocks)
            .arg(imageBlocks);
    if (!differingBlocks.isEmpty())
        text += QCoreApplication::translate("cambench::usecases", "; first differing blocks: %1")
                    .arg(differingBlocks.join(QLatin1String(", ")));
    if (!identityMismatch.isEmpty())
        text += QStringLiteral("; %1").arg(identityMismatch.join(QLatin1Char(' ')));
    return text;
}

Result<VerifyReport> verifyImage(CamConDevice& connection, const EepromImage& image,
                                 const UseCaseProgress& progress) {
    const Result<EepromImage> device = backupDevice(connection, progress);
    if (!device) return device.error();
    VerifyReport report;
    report.deviceBlocks = int(device->blocks.size());
    report.imageBlocks = int(image.blocks.size());
    report.differingBlocks = differingEepromBlocks(device->blocks, image.blocks);
    report.identityMismatch = identityMismatch(image.device, device->device);
    report.equal = report.differingBlocks.isEmpty();
    return report;
}

}  // namespace cambench::usecases
