#include "compax3_backup_part.h"

#include "compax3_parameters.h"

#include "comm/device/job.h"

#include <QCoreApplication>

namespace cambench::usecases {

namespace {

using comm::Compax3Device;
using comm::JobContext;

struct Loaded {
    Compax3ParameterSet set;
    Compax3Device* device = nullptr;
};

Result<Loaded> loadFor(JobContext& job, const QString& path) {
    const Result<Compax3ParameterSet> set = loadCompax3Parameters(path);
    if (!set) return set.error();
    const Result<Compax3Device*> device = job.family<Compax3Device>();
    if (!device) return device.error();
    return Loaded{*set, *device};
}

Compax3RestoreOptions optionsOf(const RestoreRequest& request) {
    Compax3RestoreOptions options;
    options.replacement = request.replacement;
    options.force = request.force;
    return options;
}

class Compax3Backups final : public FamilyBackup {
public:
    Result<BackupTaken> backup(JobContext& job, const QString& path) const override {
        const Result<Compax3Device*> device = job.family<Compax3Device>();
        if (!device) return device.error();
        const Compax3Dictionary& dictionary = (*device)->dictionary();
        const Result<Compax3Backup> backup = takeCompax3Parameters(
            **device, dictionary.parameters(), dictionary, UseCaseProgress::of(job));
        if (!backup) return backup.error();
        if (const Status saved = saveCompax3Parameters(path, backup->set); !saved)
            return saved.error();
        BackupTaken taken;
        taken.path = path;
        taken.identity = backup->set.drive.deviceIdentity();
        taken.summary =
            QCoreApplication::translate("cambench::usecases", "%1 objects of %2 (serial number %3)")
                .arg(backup->set.values.size())
                .arg(backup->set.drive.info, backup->set.drive.serial);
        if (!backup->set.absent.isEmpty())
            taken.summary += QCoreApplication::translate("cambench::usecases",
                                                         "; %1 objects are not on this drive")
                                 .arg(backup->set.absent.size());
        for (const Compax3Refusal& refusal : backup->refused)
            taken.incomplete << QCoreApplication::translate("cambench::usecases",
                                                            "%1: not saved: %2")
                                    .arg(refusal.id.text(), refusal.reason);
        return taken;
    }

    Result<DeviceIdentity> fileIdentity(const QString& path) const override {
        const Result<Compax3ParameterSet> set = loadCompax3Parameters(path);
        if (!set) return set.error();
        return set->drive.deviceIdentity();
    }

    Result<BackupComparison> verify(JobContext& job, const QString& path) const override {
        const Result<Loaded> loaded = loadFor(job, path);
        if (!loaded) return loaded.error();
        const Compax3Dictionary& dictionary = loaded->device->dictionary();
        const Result<Compax3Comparison> comparison = compareCompax3Parameters(
            *loaded->device, loaded->set, dictionary, UseCaseProgress::of(job));
        if (!comparison) return comparison.error();
        BackupComparison result;
        result.compared = comparison->compared;
        result.differences = compax3ComparisonItems(*comparison, loaded->set, dictionary);
        if (comparison->absentOnBoth > 0)
            result.notes << QCoreApplication::translate(
                                "cambench::usecases",
                                "%1 objects are not on this drive, nor on the file's")
                                .arg(comparison->absentOnBoth);
        for (const Compax3Refusal& ignored : comparison->ignored)
            result.notes << QCoreApplication::translate("cambench::usecases",
                                                        "%1: not compared: %2")
                                .arg(ignored.id.text(), ignored.reason);
        return result;
    }

    Result<BackupComparison> diff(const QString& first, const QString& second) const override {
        const Result<Compax3ParameterSet> before = loadCompax3Parameters(first);
        if (!before) return before.error();
        const Result<Compax3ParameterSet> after = loadCompax3Parameters(second);
        if (!after) return after.error();
        return BackupComparison{int(before->values.size() + before->absent.size()),
                                diffCompax3Sets(*before, *after, Compax3Dictionary::builtin()),
                                {}};
    }

    Result<RestorePlan> plan(JobContext& job, const QString& path,
                             const RestoreRequest& request) const override {
        const Result<Loaded> loaded = loadFor(job, path);
        if (!loaded) return loaded.error();
        const Result<QList<BackupDifference>> changes =
            planCompax3Restore(*loaded->device, loaded->set, loaded->device->dictionary(),
                               optionsOf(request), UseCaseProgress::of(job));
        if (!changes) return changes.error();
        return RestorePlan{
            *changes,
            {QCoreApplication::translate("cambench::usecases",
                                         "only the differing objects are written, each read back; "
                                         "control words and functions never from a file")}};
    }

    Result<RestoreResult> restore(JobContext& job, const QString& path,
                                  const RestoreRequest& request) const override {
        const Result<Loaded> loaded = loadFor(job, path);
        if (!loaded) return loaded.error();
        const Result<OutcomeTally> tally =
            restoreCompax3Parameters(*loaded->device, loaded->set, loaded->device->dictionary(),
                                     optionsOf(request), UseCaseProgress::of(job));
        if (!tally) return tally.error();
        return RestoreResult{*tally, {}};
    }
};

}  // namespace

std::shared_ptr<const FamilyBackup> compax3Backup() {
    return std::make_shared<Compax3Backups>();
}

}  // namespace cambench::usecases
