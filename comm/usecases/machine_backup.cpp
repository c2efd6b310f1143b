#include "machine_backup.h"

#include "comm/device/device_connection.h"
#include "comm/device/job.h"

#include <QCoreApplication>
#include <QDir>

namespace cambench::usecases {

namespace {

QString tr(const char* text) {
    return QCoreApplication::translate("cambench::usecases", text);
}

// Who answers on the job's line, compared with `expected`.
Result<DeviceChecked> check(comm::JobContext& job, const DeviceIdentity& expected,
                            const ReplacementConsent& consent) {
    comm::DeviceConnection* connection = job.device();
    if (!connection) {
        // JobContext::family says why (not connected).
        const Result<comm::DeviceConnection*> none = job.family<comm::DeviceConnection>();
        return none ? Error::communication(tr("not connected")) : none.error();
    }
    const Result<DeviceAnswer> found = whoAnswers(*connection);
    if (!found) return found.error();
    DeviceChecked checked{*found, {}};
    if (expected.known() && found->identity != expected && !consent.accepts(found->identity))
        checked.another = anotherDeviceText(expected, found->identity);
    return checked;
}

Result<const FamilyBackup*> partOf(const QString& family) {
    if (const FamilyBackup* part = BackupRegistry::instance().find(family)) return part;
    return Error::usage(tr("the %1 family has no backup").arg(family));
}

}  // namespace

Result<DeviceAnswer> whoAnswers(comm::DeviceConnection& connection) {
    const Result<QString> text = connection.identify();
    if (!text) return text.error();
    const Result<DeviceIdentity> identity = connection.readIdentity();
    if (!identity) return identity.error();
    return DeviceAnswer{*text, *identity};
}

DeviceBackedUp backUpMachineDevice(comm::JobContext& job, const MachineDevice& device,
                                   const QString& dir, bool replacement) {
    DeviceBackedUp done;
    done.entry.name = device.name;
    done.entry.family = device.family;
    done.entry.file = deviceFileName(device.name);
    const auto fail = [&done](const Error& error, const QString& result) {
        done.error = error;
        done.entry.result = tr("failed: %1").arg(result);
        return done;
    };
    const Result<const FamilyBackup*> part = partOf(device.family);
    if (!part) return fail(part.error(), part.error().message);
    const Result<DeviceChecked> checked =
        check(job, device.identity, replacement ? ReplacementConsent::any() : ReplacementConsent{});
    if (!checked) return fail(checked.error(), tr("not reached: %1").arg(checked.error().message));
    done.checked = *checked;
    done.entry.identity = checked->found.identity;
    done.entry.device = checked->found.text;
    // Saved under this name, its file would later be restored into the
    // device the machine file names.
    if (!checked->another.isEmpty())
        return fail(Error::invalidData(checked->another), checked->another);
    const QString path = QDir(dir).filePath(done.entry.file);
    const Result<BackupTaken> taken = (*part)->backup(job, path);
    done.entry.time = QDateTime::currentDateTimeUtc();
    if (!taken) return fail(taken.error(), taken.error().message);
    done.entry.summary = taken->summary;
    done.entry.incomplete = taken->incomplete;
    done.entry.sha256 = fileSha256(path);
    if (!taken->complete())
        return fail(Error::device(0, taken->incomplete.join(QLatin1Char(' '))),
                    tr("incomplete: %1").arg(taken->incomplete.join(QStringLiteral("; "))));
    done.entry.result = QStringLiteral("saved");
    return done;
}

Result<DeviceVerified> verifyMachineDevice(comm::JobContext& job, const ManifestEntry& entry,
                                           const QString& dir, const ReplacementConsent& consent) {
    const Result<const FamilyBackup*> part = partOf(entry.family);
    if (!part) return part.error();
    const Result<DeviceChecked> checked = check(job, entry.identity, consent);
    if (!checked) return checked.error();
    DeviceVerified verified{*checked, {}};
    if (!checked->another.isEmpty()) return verified;
    const Result<BackupComparison> comparison =
        (*part)->verify(job, QDir(dir).filePath(entry.file));
    if (!comparison) return comparison.error();
    verified.comparison = *comparison;
    verified.comparison.differences = onDevice(comparison->differences, entry.name);
    return verified;
}

Result<DevicePlanned> planMachineDevice(comm::JobContext& job, const ManifestEntry& entry,
                                        const QString& dir, const RestoreRequest& request) {
    const Result<const FamilyBackup*> part = partOf(entry.family);
    if (!part) return part.error();
    const Result<DeviceChecked> checked = check(job, entry.identity, request.replacement);
    if (!checked) return checked.error();
    DevicePlanned planned{*checked, {}};
    if (!checked->another.isEmpty()) return planned;
    const Result<RestorePlan> plan = (*part)->plan(job, QDir(dir).filePath(entry.file), request);
    if (!plan) return plan.error();
    planned.plan = *plan;
    planned.plan.changes = onDevice(plan->changes, entry.name);
    return planned;
}

Result<DeviceRestored> restoreMachineDevice(comm::JobContext& job, const ManifestEntry& entry,
                                            const QString& dir, const RestoreRequest& request) {
    const Result<const FamilyBackup*> part = partOf(entry.family);
    if (!part) return part.error();
    // The GUI's consent accepts exactly the identity its question showed,
    // the command line's whatever answers; the family's restore checks the
    // file's identity once more before its first byte.
    const Result<DeviceChecked> checked = check(job, entry.identity, request.replacement);
    if (!checked) return checked.error();
    DeviceRestored restored{*checked, {}};
    if (!checked->another.isEmpty()) return restored;
    const Result<RestoreResult> result =
        (*part)->restore(job, QDir(dir).filePath(entry.file), request);
    if (!result) return result.error();
    restored.result = *result;
    return restored;
}

Result<BackupComparison> diffMachineDevice(const ManifestEntry& first, const QString& firstDir,
                                           const ManifestEntry& second, const QString& secondDir) {
    if (first.family != second.family)
        return Error::invalidData(tr("%1 is a device of the %2 family in one folder and of the "
                                     "%3 family in the other: not compared")
                                      .arg(first.name, first.family, second.family));
    const Result<const FamilyBackup*> part = partOf(first.family);
    if (!part) return part.error();
    const Result<BackupComparison> compared =
        (*part)->diff(QDir(firstDir).filePath(first.file), QDir(secondDir).filePath(second.file));
    if (!compared) return compared.error();
    BackupComparison comparison = *compared;
    comparison.differences = onDevice(comparison.differences, first.name);
    return comparison;
}

}  // namespace cambench::usecases
