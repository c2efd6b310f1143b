#include "mc1_backup_part.h"

#include "mc1_backup_restore.h"

#include "comm/device/job.h"
#include "comm/mc1/mc1_variant.h"

#include <QCoreApplication>

namespace cambench::usecases {

namespace {

using comm::JobContext;
using comm::Mc1Device;

class Mc1Backups final : public FamilyBackup {
public:
    Result<BackupTaken> backup(JobContext& job, const QString& path) const override {
        const Result<Mc1Device*> device = job.family<Mc1Device>();
        if (!device) return device.error();
        const Result<comm::Mc1Variant> variant = (*device)->ensureIdentified();
        if (!variant) return variant.error();
        const Result<Mc1Backup> backup =
            takeMc1Backup(**device, defaultMc1BackupScope(*variant), UseCaseProgress::of(job));
        if (!backup) return backup.error();
        if (const Status saved = saveMc1Backup(path, *backup); !saved) return saved.error();
        BackupTaken taken;
        taken.path = path;
        taken.identity = backup->identity;
        taken.summary =
            QCoreApplication::translate("cambench::usecases", "%1 variables and %2 flags of the %3")
                .arg(backup->variables.size())
                .arg(backup->flags.size() * 8)
                .arg(comm::mc1VariantName(*variant));
        return taken;
    }

    Result<DeviceIdentity> fileIdentity(const QString& path) const override {
        const Result<Mc1Backup> backup = loadMc1Backup(path);
        if (!backup) return backup.error();
        return backup->identity;
    }

    Result<BackupComparison> verify(JobContext& job, const QString& path) const override {
        const Result<Mc1Backup> backup = loadMc1Backup(path);
        if (!backup) return backup.error();
        const Result<Mc1Device*> device = job.family<Mc1Device>();
        if (!device) return device.error();
        const Result<Mc1VerifyReport> report =
            verifyMc1Backup(**device, *backup, UseCaseProgress::of(job));
        if (!report) return report.error();
        return BackupComparison{report->compared, report->items, {}};
    }

    Result<BackupComparison> diff(const QString& first, const QString& second) const override {
        const Result<Mc1Backup> before = loadMc1Backup(first);
        if (!before) return before.error();
        const Result<Mc1Backup> after = loadMc1Backup(second);
        if (!after) return after.error();
        return BackupComparison{mc1ItemCount(*before), diffMc1Backups(*before, *after), {}};
    }

    Result<RestorePlan> plan(JobContext& job, const QString& path,
                             const RestoreRequest& request) const override {
        const Result<Mc1Backup> backup = loadMc1Backup(path);
        if (!backup) return backup.error();
        const Result<Mc1Device*> device = job.family<Mc1Device>();
        if (!device) return device.error();
        const Result<QList<BackupDifference>> changes =
            planMc1Restore(**device, *backup, request.replacement, UseCaseProgress::of(job));
        if (!changes) return changes.error();
        return RestorePlan{*changes,
                           {QCoreApplication::translate(
                               "cambench::usecases",
                               "only the differing variables, flags and memory are written, "
                               "each read back")}};
    }

    Result<RestoreResult> restore(JobContext& job, const QString& path,
                                  const RestoreRequest& request) const override {
        const Result<Mc1Backup> backup = loadMc1Backup(path);
        if (!backup) return backup.error();
        const Result<Mc1Device*> device = job.family<Mc1Device>();
        if (!device) return device.error();
        const Result<OutcomeTally> tally =
            restoreMc1Backup(**device, *backup, request.replacement, UseCaseProgress::of(job));
        if (!tally) return tally.error();
        return RestoreResult{*tally, {}};
    }
};

}  // namespace

std::shared_ptr<const FamilyBackup> mc1Backup() {
    return std::make_shared<Mc1Backups>();
}

}  // namespace cambench::usecases
