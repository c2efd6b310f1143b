#include "camcon_backup_part.h"

#include "backup_restore.h"
#include "read_everything.h"

#include "comm/device/job.h"
#include "model/camcon/eeprom_image_file.h"
#include "model/camcon/project_content.h"

#include <QCoreApplication>
#include <QJsonArray>

namespace cambench::usecases {

namespace {

using comm::CamConDevice;
using comm::JobContext;

struct Loaded {
    EepromImage image;
    CamConDevice* device = nullptr;
};

Result<Loaded> loadFor(JobContext& job, const QString& path) {
    const Result<EepromImage> image = loadEepromImage(path);
    if (!image) return image.error();
    const Result<CamConDevice*> device = job.family<CamConDevice>();
    if (!device) return device.error();
    return Loaded{*image, *device};
}

// "EEPROM: blocks 0001, 0007 differ": where the blocks say more than the
// decoded content (or the image has none).
BackupDifference blocksItem(const QStringList& blocks, const QString& why) {
    const QString key = QStringLiteral("EEPROM");
    const QString text =
        QCoreApplication::translate("cambench::usecases", "EEPROM: blocks %1 differ%2")
            .arg(blocks.join(QStringLiteral(", ")), why);
    return {{},
            key,
            QCoreApplication::translate("cambench::usecases", "blocks"),
            {},
            blocks.join(QStringLiteral(", ")),
            ChangeKind::Changed,
            text};
}

// The image against the device whose blocks differ from it: the content
// compared item by item (old = `fileIsOld` ? the image's : the device's).
Result<QList<BackupDifference>> contentDifferences(CamConDevice& device, const EepromImage& image,
                                                   const VerifyReport& blocks, bool fileIsOld,
                                                   const UseCaseProgress& progress) {
    if (image.content.isEmpty())
        return QList<BackupDifference>{
            blocksItem(blocks.differingBlocks,
                       QCoreApplication::translate(
                           "cambench::usecases",
                           " (a backup of the older format: its content is not decoded)"))};
    const Result<Project> file = projectFromContent(image.content, image.device);
    if (!file) return file.error();
    const Result<DeviceInfo> info = device.readInfo();
    if (!info) return info.error();
    const Result<ReadEverything> now = readEverything(device, *info, progress);
    if (!now) return now.error();
    QList<BackupDifference> differences = fileIsOld ? diffProjectContent(*file, now->project)
                                                    : diffProjectContent(now->project, *file);
    if (differences.isEmpty())
        differences << blocksItem(
            blocks.differingBlocks,
            QCoreApplication::translate(
                "cambench::usecases",
                " (the decoded content is equal: what differs is not in it)"));
    return differences;
}

class CamConBackups final : public FamilyBackup {
public:
    Result<BackupTaken> backup(JobContext& job, const QString& path) const override {
        const Result<CamConDevice*> device = job.family<CamConDevice>();
        if (!device) return device.error();
        const Result<EepromImage> image =
            backupToFile(**device, path, UseCaseProgress::of(job), BackupContent::Decoded);
        if (!image) return image.error();
        BackupTaken taken;
        taken.path = path;
        taken.identity = camConIdentity(image->device);
        taken.summary =
            QCoreApplication::translate("cambench::usecases",
                                        "%1 EEPROM blocks (%2 bytes), decoded: %3 programs")
                .arg(image->blocks.size())
                .arg(image->totalBytes())
                .arg(image->content.value(QStringLiteral("programs")).toArray().size());
        return taken;
    }

    Result<DeviceIdentity> fileIdentity(const QString& path) const override {
        const Result<EepromImage> image = loadEepromImage(path);
        if (!image) return image.error();
        return camConIdentity(image->device);
    }

    Result<BackupComparison> verify(JobContext& job, const QString& path) const override {
        const Result<Loaded> loaded = loadFor(job, path);
        if (!loaded) return loaded.error();
        const UseCaseProgress progress = UseCaseProgress::of(job);
        const Result<VerifyReport> blocks =
            verifyImage(*loaded->device, loaded->image, progress.slice(0, 1, 2));
        if (!blocks) return blocks.error();
        BackupComparison comparison;
        comparison.compared = blocks->imageBlocks;
        comparison.notes = blocks->identityMismatch;
        if (blocks->equal) return comparison;
        const Result<QList<BackupDifference>> differences = contentDifferences(
            *loaded->device, loaded->image, *blocks, true, progress.slice(1, 1, 2));
        if (!differences) return differences.error();
        comparison.differences = *differences;
        return comparison;
    }

    Result<BackupComparison> diff(const QString& first, const QString& second) const override {
        const Result<EepromImage> before = loadEepromImage(first);
        if (!before) return before.error();
        const Result<EepromImage> after = loadEepromImage(second);
        if (!after) return after.error();
        return diffImages(*before, *after);
    }

    Result<RestorePlan> plan(JobContext& job, const QString& path,
                             const RestoreRequest& request) const override {
        const Result<Loaded> loaded = loadFor(job, path);
        if (!loaded) return loaded.error();
        const Result<DeviceInfo> info = loaded->device->readInfo();
        if (!info) return info.error();
        if (const Status target =
                checkRestoreTarget(camConIdentity(loaded->image.device), camConIdentity(*info),
                                   request.replacement, path);
            !target)
            return target.error();
        const UseCaseProgress progress = UseCaseProgress::of(job);
        const Result<VerifyReport> blocks =
            verifyImage(*loaded->device, loaded->image, progress.slice(0, 1, 2));
        if (!blocks) return blocks.error();
        RestorePlan plan;
        plan.steps << QCoreApplication::translate(
                          "cambench::usecases",
                          "a safety copy of what the device holds now is saved first%1")
                          .arg(request.safetyCopy.isEmpty()
                                   ? QString()
                                   : QStringLiteral(" (%1)").arg(request.safetyCopy))
                   << QCoreApplication::translate(
                          "cambench::usecases",
                          "then the whole EEPROM is erased and written again: %1 blocks, "
                          "and the device starts")
                          .arg(loaded->image.blocks.size());
        if (blocks->equal) return plan;
        const Result<QList<BackupDifference>> changes = contentDifferences(
            *loaded->device, loaded->image, *blocks, false, progress.slice(1, 1, 2));
        if (!changes) return changes.error();
        plan.changes = *changes;
        return plan;
    }

    Result<RestoreResult> restore(JobContext& job, const QString& path,
                                  const RestoreRequest& request) const override {
        const Result<Loaded> loaded = loadFor(job, path);
        if (!loaded) return loaded.error();
        RestoreOptions options;
        options.replacement = request.replacement;
        options.safetyBackupPath = request.safetyCopy;
        const RestoreReport report =
            restoreImage(*loaded->device, loaded->image, path, options, UseCaseProgress::of(job));
        // Refused or failed before the erase: nothing was written.
        if (report.state == RestoredState::Unchanged) {
            Error error = report.error;
            if (!report.safetyBackupPath.isEmpty())
                error.message += QCoreApplication::translate("cambench::usecases",
                                                             " (a safety copy was saved to %1)")
                                     .arg(report.safetyBackupPath);
            return error;
        }
        const QString label = QCoreApplication::translate("cambench::usecases", "EEPROM, %1 blocks")
                                  .arg(report.blocks);
        const WriteState state =
            report.ok() ? WriteState::Written : WriteState::ChangedThoughFailed;
        const QString actual = report.ok() ? QString()
                                           : QCoreApplication::translate(
                                                 "cambench::usecases", "erased or partly written");
        return RestoreResult{
            OutcomeTally({OutcomeLine{
                label, state, outcomeText(label, state, actual, report.error, {}), report.error}}),
            report.safetyBackupPath};
    }

private:
    static Result<BackupComparison> diffImages(const EepromImage& before,
                                               const EepromImage& after) {
        BackupComparison comparison;
        comparison.compared = int(before.blocks.size());
        if (before.blocks == after.blocks) return comparison;
        if (!before.content.isEmpty() && !after.content.isEmpty()) {
            const Result<Project> one = projectFromContent(before.content, before.device);
            if (!one) return one.error();
            const Result<Project> two = projectFromContent(after.content, after.device);
            if (!two) return two.error();
            comparison.differences = diffProjectContent(*one, *two);
        }
        if (comparison.differences.isEmpty()) {
            VerifyReport blocks;
            blocks.differingBlocks = differingEepromBlocks(before.blocks, after.blocks);
            comparison.differences << blocksItem(
                blocks.differingBlocks,
                before.content.isEmpty() || after.content.isEmpty()
                    ? QCoreApplication::translate(
                          "cambench::usecases",
                          " (a backup of the older format: its content is not decoded)")
                    : QCoreApplication::translate(
                          "cambench::usecases",
                          " (the decoded content is equal: what differs is not in it)"));
        }
        return comparison;
    }
};

}  // namespace

std::shared_ptr<const FamilyBackup> camconBackup() {
    return std::make_shared<CamConBackups>();
}

}  // namespace cambench::usecases
