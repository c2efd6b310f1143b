#include "line_backup.h"

#include "backup_restore.h"

#include "model/camcon/eeprom_image_file.h"
#include "model/file_read.h"

#include <QCoreApplication>
#include <QDir>
#include <QRegularExpression>

namespace cambench::usecases {

namespace {

using comm::CamConCapability;
using comm::CamConDevice;

QDateTime now() {
    return QDateTime::currentDateTimeUtc();
}

// Per-device progress as a UseCaseProgress for the device calls.
UseCaseProgress deviceProgress(const UseCaseProgress& overall, const DeviceProgressFn& perDevice,
                               int device) {
    return UseCaseProgress(
        [perDevice, device](qint64 done, qint64 total, const QString& text) {
            if (perDevice) perDevice(device, done, total, text);
        },
        [overall] { return overall.cancelled(); });
}

// Whether the image an earlier run saved is still there and intact: the
// file's SHA-256 matches the manifest and the image's own hash checks.
bool stillSaved(const QDir& dir, const LineManifestEntry& entry) {
    if (entry.outcome != LineManifestEntry::Outcome::Saved || entry.file.isEmpty()) return false;
    const QString path = dir.filePath(entry.file);
    const Result<QByteArray> bytes = readFileBytes(path);
    return bytes && sha256Hex(*bytes) == entry.sha256 && loadEepromImage(path).ok();
}

// Backs up one device into `dir`; the entry says what happened.
LineManifestEntry backupOne(CamConDevice& connection, const QDir& dir, int device,
                            const UseCaseProgress& progress) {
    LineManifestEntry entry;
    entry.device = device;
    connection.setDevice(device);
    const Result<DeviceInfo> info = connection.readInfo();
    if (!info) {
        entry.time = now();
        entry.message = info.error().message;
        return entry;
    }
    entry.identity = *info;
    const Result<EepromImage> image = backupDevice(connection, progress);
    entry.time = now();
    if (!image) {
        entry.message = image.error().message;
        return entry;
    }
    const QString file = lineImageName(device, *info);
    const QString path = dir.filePath(file);
    if (const Status saved = saveEepromImage(path, *image); !saved) {
        entry.message = saved.error().message;
        return entry;
    }
    // Read the file back: what the manifest vouches for is what is on disk.
    const Result<QByteArray> bytes = readFileBytes(path);
    const Result<EepromImage> again = loadEepromImage(path);
    if (!bytes || !again || again->blocks != image->blocks) {
        entry.message =
            QCoreApplication::translate("cambench::usecases",
                                        "%1 was written but does not read back as the image "
                                        "taken; check the disk")
                .arg(path);
        return entry;
    }
    entry.file = file;
    entry.sha256 = sha256Hex(*bytes);
    entry.outcome = LineManifestEntry::Outcome::Saved;
    return entry;
}

Result<QList<int>> devicesOfLine(CamConDevice& connection, const LineBackupOptions& options,
                                 const UseCaseProgress& progress) {
    if (!options.devices.isEmpty()) return options.devices;
    if (!connection.has(CamConCapability::BusScan))
        return connection.missing(CamConCapability::BusScan);
    Result<QList<int>> found = connection.scanBus(
        0, 63,
        progress.forDevice(QCoreApplication::translate("cambench::usecases", "scanning the line")));
    if (!found) return found.error();
    if (found->isEmpty())
        return Error::communication(QCoreApplication::translate(
            "cambench::usecases",
            "no device answered on the line (numbers 0..63); check the cable, the "
            "baud rate and the protocol"));
    return found;
}

}  // namespace

QString lineImageName(int device, const DeviceInfo& identity) {
    QString date = identity.epromDate;
    date.replace(QRegularExpression(QStringLiteral("[^0-9A-Za-z.-]")), QStringLiteral("-"));
    return QStringLiteral("device-%1_%2_%3out.json")
        .arg(device, 2, 10, QLatin1Char('0'))
        .arg(date.isEmpty() ? QStringLiteral("unknown") : date)
        .arg(identity.outputs);
}

Result<LineManifest> backupLine(CamConDevice& connection, const LineBackupOptions& options,
                                const UseCaseProgress& progress,
                                const DeviceProgressFn& perDevice) {
    if (!connection.has(CamConCapability::EepromBackup))
        return connection.missing(CamConCapability::EepromBackup);
    QDir dir(options.directory);
    if (!dir.mkpath(QStringLiteral(".")))
        return Error::usage(
            QCoreApplication::translate("cambench::usecases",
                                        "cannot create the folder %1; choose another one")
                .arg(options.directory));
    const QString manifestPath = dir.filePath(QLatin1String(kLineManifestName));
    LineManifest manifest;
    if (options.resume && QFileInfo::exists(manifestPath)) {
        Result<LineManifest> earlier = loadLineManifest(manifestPath);
        if (!earlier) return earlier.error();
        manifest = *earlier;
    }
    manifest.line = options.lineDescription;

    const Result<QList<int>> devices = devicesOfLine(connection, options, progress);
    if (!devices) return devices.error();
    for (int i = 0; i < devices->size(); ++i) {
        const int device = devices->at(i);
        progress.report(i, devices->size(),
                        QCoreApplication::translate("cambench::usecases", "device %1").arg(device));
        if (progress.cancelled()) {
            if (i == 0) return Error::cancelled();
            LineManifestEntry entry;
            entry.device = device;
            entry.time = now();
            entry.message = QCoreApplication::translate("cambench::usecases",
                                                        "not backed up: the run was cancelled");
            if (const LineManifestEntry* earlier = manifest.find(device);
                !earlier || !stillSaved(dir, *earlier))
                manifest.put(entry);
            continue;
        }
        if (options.resume) {
            if (const LineManifestEntry* earlier = manifest.find(device);
                earlier && stillSaved(dir, *earlier)) {
                if (perDevice)
                    perDevice(device, 1, 1,
                              QCoreApplication::translate("cambench::usecases",
                                                          "saved by an earlier run"));
                continue;
            }
        }
        manifest.put(
            backupOne(connection, dir, device, deviceProgress(progress, perDevice, device)));
        // After every device: a run cut off later still leaves a true manifest.
        if (const Status saved = saveLineManifest(manifestPath, manifest); !saved)
            return saved.error();
    }
    progress.report(devices->size(), devices->size(),
                    QCoreApplication::translate("cambench::usecases", "line backed up"));
    if (const Status saved = saveLineManifest(manifestPath, manifest); !saved) return saved.error();
    return manifest;
}

Result<QList<LineVerifyEntry>> verifyLine(CamConDevice& connection, const QString& directory,
                                          const UseCaseProgress& progress,
                                          const DeviceProgressFn& perDevice) {
    const QDir dir(directory);
    const Result<LineManifest> manifest =
        loadLineManifest(dir.filePath(QLatin1String(kLineManifestName)));
    if (!manifest) return manifest.error();
    QList<LineVerifyEntry> results;
    const int count = int(manifest->devices.size());
    for (int i = 0; i < count; ++i) {
        const LineManifestEntry& entry = manifest->devices.at(i);
        progress.report(
            i, count,
            QCoreApplication::translate("cambench::usecases", "device %1").arg(entry.device));
        if (progress.cancelled()) return Error::cancelled();
        LineVerifyEntry result{entry.device, entry.file, false, {}};
        const QString prefix =
            QCoreApplication::translate("cambench::usecases", "device %1: ").arg(entry.device);
        if (entry.outcome != LineManifestEntry::Outcome::Saved) {
            result.text = prefix + QCoreApplication::translate(
                                       "cambench::usecases", "not verified: its backup failed (%1)")
                                       .arg(entry.message);
            results << result;
            continue;
        }
        const QString path = dir.filePath(entry.file);
        const Result<QByteArray> bytes = readFileBytes(path);
        if (!bytes || sha256Hex(*bytes) != entry.sha256) {
            result.text = prefix + QCoreApplication::translate(
                                       "cambench::usecases",
                                       "%1 is missing or was changed since the backup "
                                       "(SHA-256 differs from the manifest)")
                                       .arg(entry.file);
            results << result;
            continue;
        }
        const Result<EepromImage> image = loadEepromImage(path);
        if (!image) {
            result.text = prefix + image.error().message;
            results << result;
            continue;
        }
        connection.setDevice(entry.device);
        const Result<VerifyReport> verified =
            verifyImage(connection, *image, deviceProgress(progress, perDevice, entry.device));
        if (!verified) {
            result.text = prefix + verified.error().message;
            if (verified.error().kind == ErrorKind::Cancelled) return verified.error();
        } else {
            result.equal = verified->equal;
            result.text = prefix + verified->text(entry.file);
        }
        results << result;
    }
    progress.report(count, count,
                    QCoreApplication::translate("cambench::usecases", "line verified"));
    return results;
}

}  // namespace cambench::usecases
