// backup, restore, verify: the whole EEPROM as an image file.
#include "cli_output.h"
#include "commands.h"
#include "exit_codes.h"

#include "model/camcon/eeprom_image_file.h"

#include <QDateTime>

namespace cambench::cli {

namespace {

using comm::CamConDevice;
using comm::JobContext;

comm::ProgressFn reporter(JobContext& job, const QString& text) {
    return [&job, text](qint64 done, qint64 total) { job.progress(done, total, text); };
}

Result<EepromImage> backupJob(CliSession& session, const QString& title) {
    session.setShowProgress(true);
    return session.run<EepromImage>(title, [title](CamConDevice& client, JobContext& job) {
        return client.backup(reporter(job, title));
    });
}

QString hex4(int number) {
    return QStringLiteral("%1").arg(number, 4, 16, QChar(u'0')).toUpper();
}

// Block numbers where the device and the image differ, first ones only.
QStringList differingBlocks(const QList<EepromBlock>& device, const QList<EepromBlock>& image) {
    constexpr int kListed = 10;
    QStringList differences;
    const int count = int(qMax(device.size(), image.size()));
    for (int i = 0; i < count && differences.size() < kListed; ++i) {
        if (i < device.size() && i < image.size() && device.at(i) == image.at(i)) continue;
        const int number = i < image.size() ? image.at(i).number : device.at(i).number;
        differences.append(hex4(number));
    }
    return differences;
}

// "<image>.safety-20261121T231500Z.json" next to the image.
QString safetyBackupPath(const QString& imagePath) {
    return QStringLiteral("%1.safety-%2.json")
        .arg(imagePath,
             QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyyMMdd'T'HHmmss'Z'")));
}

}  // namespace

int runBackup(CliSession& session, CommandArgs& args) {
    const Result<QString> path =
        args.takeOption(QStringLiteral("--output-file"), QStringLiteral("-o"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    if (path->isEmpty()) return reportError(Error::usage(QStringLiteral("backup needs -o FILE")));
    const Result<EepromImage> image = backupJob(session, QStringLiteral("backup"));
    if (!image) return reportError(image.error());
    const Status saved = saveEepromImage(*path, *image);
    if (!saved) return reportError(saved.error());
    printOut(QStringLiteral("saved %1 EEPROM blocks (%2 bytes) to %3\n")
                 .arg(image->blocks.size())
                 .arg(image->totalBytes())
                 .arg(*path));
    return ExitOk;
}

int runRestore(CliSession& session, CommandArgs& args) {
    const bool force = args.takeFlag(QStringLiteral("--force"));
    const bool noSafety = args.takeFlag(QStringLiteral("--no-safety-backup"));
    const Result<QString> path = args.takeRequiredPositional(QStringLiteral("an image FILE"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());

    // Hash, version, block 0 and every block length are checked before the
    // device is even contacted.
    const Result<EepromImage> image = loadEepromImage(*path);
    if (!image) return reportError(image.error());

    const Result<DeviceInfo> device = session.run<DeviceInfo>(
        QStringLiteral("identify"), [](CamConDevice& client, JobContext&) -> Result<DeviceInfo> {
            if (!client.has(comm::CamConCapability::EepromBackup))
                return client.missing(comm::CamConCapability::EepromBackup);
            return client.readInfo();
        });
    if (!device) return reportError(device.error());
    const QStringList mismatch = identityMismatch(image->device, *device);
    if (!mismatch.isEmpty() && !force) {
        return reportError(Error::invalidData(
            QStringLiteral("%1 was taken from another kind of device: %2 Add --force to restore it "
                           "anyway (the device was not changed)")
                .arg(*path, mismatch.join(u' '))));
    }

    QString safetyPath;
    if (!noSafety) {
        const Result<EepromImage> safety = backupJob(session, QStringLiteral("safety backup"));
        if (!safety) {
            Error error = safety.error();
            error.message = QStringLiteral(
                                "cannot take the safety backup before the restore: %1 "
                                "The device was not changed.")
                                .arg(error.message);
            return reportError(error);
        }
        safetyPath = safetyBackupPath(*path);
        const Status saved = saveEepromImage(safetyPath, *safety);
        if (!saved) return reportError(saved.error());
        printError(QStringLiteral("safety backup of the device saved to %1").arg(safetyPath));
    }

    const EepromImage blocks = *image;
    const Status restored = session.run<Done>(
        QStringLiteral("restore"), [blocks](CamConDevice& client, JobContext& job) {
            return client.restore(blocks, reporter(job, QStringLiteral("restore")));
        });
    if (!restored) {
        Error error = restored.error();
        error.message += safetyPath.isEmpty()
                             ? QStringLiteral(" No safety backup was taken (--no-safety-backup).")
                             : QStringLiteral(
                                   " The device's previous content is in the safety "
                                   "backup %1.")
                                   .arg(safetyPath);
        error.message += QStringLiteral(
            " Nothing else was changed. Run the same restore command "
            "again once the connection works.");
        return reportError(error);
    }
    printOut(
        QStringLiteral("restored %1 EEPROM blocks from %2\n").arg(image->blocks.size()).arg(*path));
    return ExitOk;
}

int runVerify(CliSession& session, CommandArgs& args) {
    const Result<QString> path = args.takeRequiredPositional(QStringLiteral("an image FILE"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<EepromImage> image = loadEepromImage(*path);
    if (!image) return reportError(image.error());
    const Result<EepromImage> device = backupJob(session, QStringLiteral("verify"));
    if (!device) return reportError(device.error());
    const QStringList differences = differingBlocks(device->blocks, image->blocks);
    if (differences.isEmpty()) {
        printOut(QStringLiteral("the device equals %1 (%2 blocks)\n")
                     .arg(*path)
                     .arg(image->blocks.size()));
        return ExitOk;
    }
    printOut(QStringLiteral("the device differs from %1: device %2 blocks, image %3 blocks; "
                            "first differing blocks: %4\n")
                 .arg(*path)
                 .arg(device->blocks.size())
                 .arg(image->blocks.size())
                 .arg(differences.join(QLatin1String(", "))));
    return ExitDevice;  // documented: verify exits 1 when the device differs
}

}  // namespace cambench::cli
