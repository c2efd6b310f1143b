#include "fake_backup.h"

#include "fake_family.h"

#include "comm/device/job.h"
#include "model/atomic_file.h"
#include "model/file_read.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>

namespace cambench::fake {

namespace {

using comm::JobContext;
using usecases::BackupComparison;
using usecases::BackupTaken;
using usecases::OutcomeLine;
using usecases::RestorePlan;
using usecases::RestoreRequest;
using usecases::RestoreResult;
using usecases::WriteState;

const QString kFormat = QStringLiteral("cambench-fake-backup");

// What a file holds: who the device was, and its registers (n -> value).
struct FakeImage {
    DeviceIdentity identity;
    QMap<int, qint32> registers;
};

QByteArray imageJson(const FakeImage& image) {
    QJsonObject registers;
    for (auto it = image.registers.cbegin(); it != image.registers.cend(); ++it)
        registers.insert(QString::number(it.key()), it.value());
    return QJsonDocument(QJsonObject{{QStringLiteral("format"), kFormat},
                                     {QStringLiteral("identity"), image.identity.toJson()},
                                     {QStringLiteral("registers"), registers}})
        .toJson();
}

Result<FakeImage> loadImage(const QString& path) {
    const Result<QByteArray> bytes = readFileBytes(path);
    if (!bytes) return bytes.error();
    const QJsonObject root = QJsonDocument::fromJson(*bytes).object();
    if (root.value(QStringLiteral("format")).toString() != kFormat)
        return Error::invalidData(QStringLiteral("%1: not a fake device's backup").arg(path));
    const Result<DeviceIdentity> identity =
        DeviceIdentity::fromJson(root.value(QStringLiteral("identity")), path);
    if (!identity) return identity.error();
    FakeImage image{*identity, {}};
    const QJsonObject registers = root.value(QStringLiteral("registers")).toObject();
    for (auto it = registers.begin(); it != registers.end(); ++it)
        image.registers.insert(it.key().toInt(), it.value().toInt());
    return image;
}

Result<FakeDevice*> identified(JobContext& job) {
    Result<FakeDevice*> device = job.family<FakeDevice>();
    if (!device) return device.error();
    if (const Result<QString> id = (*device)->identify(); !id) return id.error();
    return device;
}

Result<FakeImage> readImage(FakeDevice& device) {
    FakeImage image{device.identity(), {}};
    for (int n = 1; n <= device.registers(); ++n) {
        const Result<qint32> value = device.readRegister(n);
        if (!value) return value.error();
        image.registers.insert(n, *value);
    }
    return image;
}

// old -> new, register by register ("R2 201 -> 77").
QList<BackupDifference> differences(const FakeImage& older, const FakeImage& newer) {
    QList<BackupDifference> list;
    QMap<int, qint32> all = older.registers;
    all.insert(newer.registers);
    for (auto it = all.cbegin(); it != all.cend(); ++it) {
        const int n = it.key();
        const bool inOld = older.registers.contains(n);
        const bool inNew = newer.registers.contains(n);
        if (inOld && inNew && older.registers.value(n) == newer.registers.value(n)) continue;
        BackupDifference difference;
        difference.key = QStringLiteral("R%1").arg(n);
        if (inOld) difference.oldValue = QString::number(older.registers.value(n));
        if (inNew) difference.newValue = QString::number(newer.registers.value(n));
        difference.kind =
            !inOld ? ChangeKind::Added : (!inNew ? ChangeKind::Removed : ChangeKind::Changed);
        difference.text = difference.key + QLatin1Char(' ') +
                          changeText(difference.kind, difference.oldValue, difference.newValue);
        list << difference;
    }
    return list;
}

// The file, and the device that answers checked against it before any write.
struct Checked {
    FakeImage file;
    FakeImage device;
    FakeDevice* connection = nullptr;
};
Result<Checked> checkedRestore(JobContext& job, const QString& path,
                               const RestoreRequest& request) {
    const Result<FakeImage> file = loadImage(path);
    if (!file) return file.error();
    const Result<FakeDevice*> device = identified(job);
    if (!device) return device.error();
    if (const Status target =
            checkRestoreTarget(file->identity, (*device)->identity(), request.replacement, path);
        !target)
        return target.error();
    if ((*device)->registers() != file->registers.size())
        return Error::invalidData(
            QStringLiteral("%1 holds %2 registers, the device has %3: nothing was written")
                .arg(path)
                .arg(file->registers.size())
                .arg((*device)->registers()));
    const Result<FakeImage> now = readImage(**device);
    if (!now) return now.error();
    return Checked{*file, *now, *device};
}

class FakeBackups final : public usecases::FamilyBackup {
public:
    Result<BackupTaken> backup(JobContext& job, const QString& path) const override {
        const Result<FakeDevice*> device = identified(job);
        if (!device) return device.error();
        const Result<FakeImage> image = readImage(**device);
        if (!image) return image.error();
        if (const Status saved = writeFileAtomically(path, imageJson(*image)); !saved)
            return saved.error();
        BackupTaken taken;
        taken.path = path;
        taken.identity = image->identity;
        taken.device = QStringLiteral("fake device %1").arg(image->identity.text());
        taken.summary = QStringLiteral("%1 registers").arg(image->registers.size());
        return taken;
    }

    Result<DeviceIdentity> fileIdentity(const QString& path) const override {
        const Result<FakeImage> image = loadImage(path);
        if (!image) return image.error();
        return image->identity;
    }

    Result<BackupComparison> verify(JobContext& job, const QString& path) const override {
        const Result<FakeImage> file = loadImage(path);
        if (!file) return file.error();
        const Result<FakeDevice*> device = identified(job);
        if (!device) return device.error();
        const Result<FakeImage> now = readImage(**device);
        if (!now) return now.error();
        return BackupComparison{int(file->registers.size()), differences(*file, *now), {}};
    }

    Result<BackupComparison> diff(const QString& first, const QString& second) const override {
        const Result<FakeImage> before = loadImage(first);
        if (!before) return before.error();
        const Result<FakeImage> after = loadImage(second);
        if (!after) return after.error();
        return BackupComparison{int(before->registers.size()), differences(*before, *after), {}};
    }

    Result<RestorePlan> plan(JobContext& job, const QString& path,
                             const RestoreRequest& request) const override {
        const Result<Checked> checked = checkedRestore(job, path, request);
        if (!checked) return checked.error();
        return RestorePlan{differences(checked->device, checked->file),
                           {QStringLiteral("only the differing registers, each read back")}};
    }

    Result<RestoreResult> restore(JobContext& job, const QString& path,
                                  const RestoreRequest& request) const override {
        const Result<Checked> checked = checkedRestore(job, path, request);
        if (!checked) return checked.error();
        QList<OutcomeLine> lines;
        for (auto it = checked->file.registers.cbegin(); it != checked->file.registers.cend();
             ++it) {
            const QString label = QStringLiteral("R%1").arg(it.key());
            if (checked->device.registers.value(it.key()) == it.value()) {
                lines << OutcomeLine{
                    label, WriteState::Unchanged, label + QStringLiteral(": unchanged"), {}};
                continue;
            }
            const Result<qint32> now = checked->connection->writeRegister(it.key(), it.value());
            if (now && *now == it.value())
                lines << OutcomeLine{
                    label, WriteState::Written, label + QStringLiteral(": written"), {}};
            else
                lines << OutcomeLine{
                    label, WriteState::Unknown, label + QStringLiteral(": not known"),
                    now ? Error::communication(QStringLiteral("read back %1").arg(*now))
                        : now.error()};
        }
        return RestoreResult{usecases::OutcomeTally(lines), {}};
    }
};

}  // namespace

std::shared_ptr<const usecases::FamilyBackup> fakeBackup() {
    return std::make_shared<FakeBackups>();
}

}  // namespace cambench::fake
